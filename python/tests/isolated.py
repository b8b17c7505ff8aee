"""Calls run in a child interpreter, so that one that crashes it (SIGSEGV, an abort) fails its own test
instead of taking pytest with it. The child finds revolve where this process did (PYTHONPATH passes
through) and reports each call's outcome as a line of JSON; when it dies in the middle of a call, the
call is marked as the crash (with how the child ended and its stderr) and a new child runs the rest.

Nothing here is timed: the timeout only stops a child that hangs, and fails the test saying so."""

import json
import os
import signal
import subprocess
import sys

HANG_TIMEOUT = 240  # seconds; a child that has not finished by then is hung, not slow

_CHILD = r"""
import json, sys
{setup}
def _outcome(call):
    try:
        value = call()
    except BaseException as error:  # noqa: B036 -- the point is to report whatever comes out
        return {{"type": type(error).__name__, "mro": [c.__name__ for c in type(error).__mro__], "message": str(error)}}
    try:
        json.dumps(value)
    except (TypeError, ValueError):
        value = repr(value)[:200]
    return {{"type": None, "value": value}}
_calls = {calls}
for _label in json.loads(sys.argv[1]):
    print(json.dumps({{"started": _label}}), flush=True)
    _result = _outcome(_calls[_label])
    _result["label"] = _label
    print(json.dumps(_result), flush=True)
"""


def child_env(**extra):
    env = dict(os.environ)  # PYTHONPATH (where revolve is) and REVOLVE_* pass through
    env.update({k: str(v) for k, v in extra.items()})
    return env


def how_it_ended(done):
    """'exit status 1' or 'killed by SIGSEGV', with the end of its stderr."""
    code = done.returncode
    if code < 0:
        try:
            ending = f"killed by {signal.Signals(-code).name}"
        except ValueError:
            ending = f"killed by signal {-code}"
    else:
        ending = f"exit status {code}"
    stderr = (done.stderr or "").strip()
    return ending + (f"; stderr ends: {stderr[-1500:]}" if stderr else "")


def run_python(code, *args, cwd=None, env=None, timeout=HANG_TIMEOUT):
    """`python -c code args...` (or, when `code` is a path, that script) in a child; its CompletedProcess."""
    # -X faulthandler: a child that crashes prints every thread's Python stack on its stderr.
    command = [sys.executable, "-X", "faulthandler"] + ([str(code)] if isinstance(code, os.PathLike) else ["-c", code])
    return subprocess.run(command + [str(a) for a in args], capture_output=True, text=True, cwd=cwd,
                          env=env if env is not None else child_env(), timeout=timeout)


def run_calls(setup, calls, cwd=None, env=None):
    """Runs each of `calls` ({label: Python expression}) after `setup` (statements) in a child and
    returns {label: outcome}: {"type": None, "value": ...} for a call that returned, {"type":
    "ValueError", "mro": [...], "message": ...} for one that raised, {"crash": "killed by SIGSEGV; ..."}
    for one during which the child died (the rest then run in a new child)."""
    body = "{" + ", ".join(f"{label!r}: (lambda: ({expression}))" for label, expression in calls.items()) + "}"
    program = _CHILD.format(setup=setup, calls=body)
    outcomes, pending = {}, list(calls)
    while pending:
        done = run_python(program, json.dumps(pending), cwd=cwd, env=env)
        started = None
        for line in done.stdout.splitlines():
            if not line.startswith("{"):
                continue
            record = json.loads(line)
            if "started" in record:
                started = record["started"]
            else:
                outcomes[record.pop("label")] = record
                started = None
        if started is not None:
            outcomes[started] = {"crash": how_it_ended(done)}
        left = [label for label in pending if label not in outcomes]
        if not left and started is None and done.returncode != 0:
            raise AssertionError(f"the child died after its last call: {how_it_ended(done)}")
        if left == pending or (started is None and done.returncode != 0):
            # Died outside any call (in the setup, or on the way out): every call left is charged with it.
            for label in left:
                outcomes[label] = {"crash": how_it_ended(done)}
            left = []
        pending = left
    return outcomes


def describe(outcome):
    if "crash" in outcome:
        return f"the interpreter died: {outcome['crash']}"
    if outcome["type"] is None:
        return f"returned {outcome['value']!r}"[:400]
    return f"raised {outcome['type']}: {outcome['message']}"[:1500]


def assert_raised(outcome, kind, *fragments):
    """The call raised `kind` (a ValueError subclass counts as a ValueError) with every fragment in its message."""
    assert "crash" not in outcome and outcome["type"] is not None and kind in outcome["mro"], (
        f"expected {kind}; {describe(outcome)}")
    for fragment in fragments:
        assert fragment in outcome["message"], f"expected {fragment!r} in the message; {describe(outcome)}"
    assert "Unable to cast" not in outcome["message"], describe(outcome)


def assert_returned(outcome):
    assert "crash" not in outcome and outcome["type"] is None, f"expected a result; {describe(outcome)}"
    return outcome["value"]

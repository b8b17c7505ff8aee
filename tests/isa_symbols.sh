#!/usr/bin/env bash
# A wider copy of the per-ray code (avx2, avx512) must define no inline (weak) function outside its
# own namespace: the linker could otherwise hand such a copy, with its instructions, to code that runs
# on any CPU. Only code counts ('W'): weak objects ('V', 'u': type_info records, which clang's UBSan
# emits for every function type it checks, and the statics of inline functions) hold no instructions.
# clang's __clang_call_terminate is two calls (__cxa_begin_catch, std::terminate) in any ISA.
# Usage: isa_symbols.sh ISA OBJECT...
set -euo pipefail
isa=$1
shift
leaks=$(nm -C --defined-only "$@" | awk '$2 == "W"' | grep -v "revolve::detail::${isa}::" |
        grep -v -x '[0-9a-f]* W __clang_call_terminate' || true)
if [[ -n "$leaks" ]]; then
  echo "weak functions outside revolve::detail::${isa} in the ${isa} objects:"
  echo "$leaks"
  exit 1
fi
echo "no weak function outside revolve::detail::${isa}"

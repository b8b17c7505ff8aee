#!/usr/bin/python3
"""Checks every relative link and image in README.md and docs/*.md: the file it names must exist,
and a #fragment must name a heading of the page it points to (GitHub's anchors). Links to the web
are not followed. Prints each broken link as FILE:LINE: and exits 1 if there is any.

    scripts/check-links.py [ROOT]     (default: the checkout holding this script)
"""
import pathlib
import re
import sys
import urllib.parse

LINK = re.compile(r"!?\[(?:[^\]\[]|\[[^\]]*\])*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")


def github_anchor(heading):
    """GitHub's anchor of a heading: lower case, markup and punctuation dropped, spaces to hyphens."""
    text = re.sub(r"`([^`]*)`", r"\1", heading)
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", text)
    text = re.sub(r"[^\w\- ]", "", text.lower())
    return text.replace(" ", "-")


def prose_lines(path):
    """(line number, text) of the lines outside fenced code blocks."""
    fenced = False
    for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        if line.lstrip().startswith("```"):
            fenced = not fenced
            continue
        if not fenced:
            yield number, line


def anchors_of(path, cache={}):
    if path not in cache:
        seen = {}
        anchors = set()
        for _, line in prose_lines(path):
            match = HEADING.match(line)
            if not match:
                continue
            anchor = github_anchor(match.group(2))
            count = seen.get(anchor, 0)
            seen[anchor] = count + 1
            anchors.add(anchor if count == 0 else f"{anchor}-{count}")
        cache[path] = anchors
    return cache[path]


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parent.parent).resolve()
    pages = [root / "README.md"] + sorted((root / "docs").glob("*.md"))
    broken = 0
    checked = 0
    for page in pages:
        for number, line in prose_lines(page):
            for match in LINK.finditer(re.sub(r"`[^`]*`", "", line)):
                target = match.group(1)
                if re.match(r"^[a-z][a-z0-9+.-]*:", target):  # http:, https:, mailto:
                    continue
                checked += 1
                location, _, fragment = target.partition("#")
                resolved = (page.parent / urllib.parse.unquote(location)).resolve() if location else page
                where = f"{page.relative_to(root)}:{number}"
                if root not in resolved.parents and resolved != root:
                    print(f"{where}: {target} points outside the checkout")
                    broken += 1
                elif not resolved.exists():
                    print(f"{where}: {target}: no such file ({resolved.relative_to(root)})")
                    broken += 1
                elif fragment and resolved.suffix == ".md" and fragment not in anchors_of(resolved):
                    print(f"{where}: {target}: {resolved.relative_to(root)} has no heading #{fragment}")
                    broken += 1
    print(f"check-links: {checked} relative links in {len(pages)} pages, {broken} broken")
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main())

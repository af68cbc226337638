#!/usr/bin/env python3
"""Checks every relative link of README.md, CHANGELOG.md and docs/*.md: the file it names exists
in the repository, and an anchor (#...) names a heading of that file, spelled as GitHub spells
heading anchors; and docs/index.md lists every other page of docs/ exactly once. Links inside
code blocks and code spans are text, not links.
Usage: python3 scripts/check_links.py [FILE.md...]   (prints each broken link; status 1 if any)"""
import pathlib
import re
import sys

root = pathlib.Path(__file__).resolve().parent.parent
link = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)\)")


def unfenced(text):
    """The text outside fenced code blocks."""
    return re.sub(r"^```.*?^```", "", text, flags=re.S | re.M)


def prose(text):
    """The text outside fenced code blocks and code spans."""
    return re.sub(r"`[^`\n]*`", "", unfenced(text))


def anchors(path):
    """GitHub's heading anchors: lower case, punctuation dropped, spaces to '-', repeats -1, -2."""
    seen, out = {}, set()
    for line in unfenced(path.read_text()).splitlines():
        m = re.match(r"#{1,6}\s+(.*?)\s*#*\s*$", line)
        if not m:
            continue
        slug = re.sub(r"[^\w\- ]", "", m.group(1).replace("`", "").lower()).replace(" ", "-")
        n = seen.get(slug, 0)
        seen[slug] = n + 1
        out.add(slug if n == 0 else f"{slug}-{n}")
    return out


files = [pathlib.Path(f).resolve() for f in sys.argv[1:]] or [
    root / "README.md", root / "CHANGELOG.md", *sorted((root / "docs").glob("*.md"))]
broken = 0
for md in files:
    for target in link.findall(prose(md.read_text())):
        if re.match(r"[a-z]+:", target):  # https:, mailto:: not checked here
            continue
        name, _, anchor = target.partition("#")
        dest = (md.parent / name).resolve() if name else md
        why = None
        if not dest.exists():
            why = "no such file"
        elif root not in dest.parents and dest != root:
            why = "outside the repository"
        elif anchor and dest.suffix == ".md" and anchor not in anchors(dest):
            why = "no such heading"
        if why:
            print(f"{md.relative_to(root)}: ({target}): {why}")
            broken += 1
# docs/index.md lists every other page of docs/ exactly once.
if not sys.argv[1:]:
    listed = re.findall(r"\]\(([\w.-]+\.md)\)", prose((root / "docs/index.md").read_text()))
    for page in sorted((root / "docs").glob("*.md")):
        n = listed.count(page.name)
        if page.name != "index.md" and n != 1:
            print(f"docs/index.md: lists {page.name} {n} times, not once")
            broken += 1
print(f"{broken} broken links" if broken else f"every relative link resolves ({len(files)} files)")
sys.exit(1 if broken else 0)

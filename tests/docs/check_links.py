"""The documentation's links: every relative link in README.md, docs/ and the example
READMEs points at a file that exists (and, for a link into a page's section, at a
heading that exists), and every page of docs/ is reachable from docs/index.md.
Usage: check_links.py SOURCE_DIR   (exit 1 with one line per problem)"""
import glob
import os
import re
import sys

root = sys.argv[1]
os.chdir(root)
pages = ["README.md"] + sorted(glob.glob("docs/**/*.md", recursive=True)) + sorted(
    glob.glob("examples/**/*.md", recursive=True))
link = re.compile(r"\]\(([^)\s]+)\)")


def anchors(path):
    """GitHub's anchors of the headings of `path`."""
    found = set()
    for line in open(path, encoding="utf-8"):
        heading = re.match(r"#+\s+(.*)", line)
        if heading:
            text = re.sub(r"[^\w\- ]", "", heading.group(1).strip().lower())
            found.add(text.replace(" ", "-"))
    return found


def links(path):
    text = re.sub(r"```.*?```", "", open(path, encoding="utf-8").read(), flags=re.S)
    return [m.group(1) for m in link.finditer(text) if not m.group(1).startswith(("http", "mailto:"))]


problems = []
for page in pages:
    for target in links(page):
        path, _, fragment = target.partition("#")
        resolved = os.path.normpath(os.path.join(os.path.dirname(page), path)) if path else page
        if not os.path.exists(resolved):
            problems.append(f"{page}: the link {target} points at nothing")
        elif fragment and resolved.endswith(".md") and fragment not in anchors(resolved):
            problems.append(f"{page}: the link {target} names no heading of {resolved}")

reached, stack = set(), ["docs/index.md"]
while stack:
    page = stack.pop()
    if page in reached or not page.endswith(".md") or not os.path.exists(page):
        continue
    reached.add(page)
    for target in links(page):
        path = target.partition("#")[0]
        if path:
            stack.append(os.path.normpath(os.path.join(os.path.dirname(page), path)))
for page in sorted(glob.glob("docs/**/*.md", recursive=True)):
    if page not in reached:
        problems.append(f"{page}: not reachable from docs/index.md")

for p in problems:
    print(p)
print(f"{len(pages)} pages read, {len(problems)} problem(s)")
sys.exit(1 if problems else 0)

#!/usr/bin/env python3
"""Checks the links of README.md, CHANGELOG.md, CONTRIBUTING.md and every docs/**/*.md: each relative link must name a file or
folder of the repository (and an existing heading where it has a #fragment), no link may leave
the repository, and every page under docs/ must be listed in docs/README.md.

    python3 tools/check_links.py [--code]

--code also lists the repository paths written in backticks (`far/refiner.h`, `tools/memory/`)
that do not exist, as warnings: code is moved more often than docs are read. Exit status 0 when
every link resolves, 1 otherwise (with one line per broken link). Standard library only.
"""

import argparse
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
LINK = re.compile(r"!?\[(?:[^\]\[]|\[[^\]]*\])*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
FENCE = re.compile(r"^\s*(```|~~~)")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")
CODE_PATH = re.compile(r"`((?:far|osd|kernels|shaders|tools|tests|bench|examples|data|docs)/[A-Za-z0-9_./{},*-]*)`")


def pages():
    """The top-level pages and every .md under docs/, as paths relative to the root."""
    found = [f for f in ("README.md", "CHANGELOG.md", "CONTRIBUTING.md") if os.path.exists(os.path.join(ROOT, f))]
    for folder, _, files in os.walk(os.path.join(ROOT, "docs")):
        found += [os.path.relpath(os.path.join(folder, f), ROOT) for f in files if f.endswith(".md")]
    return sorted(found)


def prose_lines(text):
    """(line number, line) outside fenced code blocks."""
    inside = False
    for number, line in enumerate(text.split("\n"), 1):
        if FENCE.match(line):
            inside = not inside
            continue
        if not inside:
            yield number, line


def slug(heading):
    """GitHub's anchor for a heading: lower case, punctuation dropped, spaces to hyphens."""
    text = re.sub(r"`|\*\*|\[([^\]]*)\]\([^)]*\)", r"\1", heading).strip().lower()
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def anchors(path, cache={}):
    if path not in cache:
        seen, result = {}, set()
        with open(path, encoding="utf-8") as f:
            for _, line in prose_lines(f.read()):
                m = HEADING.match(line)
                if m:
                    base = slug(m.group(2))
                    n = seen.get(base, 0)
                    seen[base] = n + 1
                    result.add(base if n == 0 else f"{base}-{n}")
        cache[path] = result
    return cache[path]


def check_link(page, target):
    """None when `target` (as written in `page`) resolves, else why not."""
    if re.match(r"^[a-z][a-z0-9+.-]*:", target):
        return f"{target} leaves the repository"
    path, _, fragment = target.partition("#")
    here = os.path.join(ROOT, page)
    resolved = here if not path else os.path.normpath(os.path.join(os.path.dirname(here), path))
    if os.path.relpath(resolved, ROOT).startswith(".."):
        return f"{target} leaves the repository"
    if not os.path.exists(resolved):
        return f"{target}: no such file or folder"
    if fragment:
        if not resolved.endswith(".md") or os.path.isdir(resolved):
            return f"{target}: a #fragment on something that is not a page"
        if fragment not in anchors(resolved):
            return f"{target}: no heading #{fragment} in {os.path.relpath(resolved, ROOT)}"
    return None


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--code", action="store_true", help="also warn about backticked repository paths that do not exist")
    args = parser.parse_args()
    errors, warnings, links = [], [], 0
    for page in pages():
        with open(os.path.join(ROOT, page), encoding="utf-8") as f:
            text = f.read()
        for number, line in prose_lines(text):
            for m in LINK.finditer(line):
                links += 1
                why = check_link(page, m.group(1))
                if why:
                    errors.append(f"{page}:{number}: {why}")
            if args.code:
                for m in CODE_PATH.finditer(line):
                    path = m.group(1).rstrip(".,")
                    if any(c in path for c in "{}*") or "decisions/" in page:
                        continue  # patterns, and the records' paths of their time
                    if not os.path.exists(os.path.join(ROOT, path)):
                        warnings.append(f"{page}:{number}: `{path}` does not exist")
    # Every page of docs/ is listed in docs/README.md.
    with open(os.path.join(ROOT, "docs", "README.md"), encoding="utf-8") as f:
        index = {os.path.normpath(os.path.join("docs", m.group(1).partition("#")[0]))
                 for _, line in prose_lines(f.read()) for m in LINK.finditer(line)}
    for page in pages():
        if page.startswith("docs/") and page != "docs/README.md" and page not in index:
            errors.append(f"docs/README.md: does not list {page}")
    for line in warnings:
        print(f"warning: {line}")
    for line in errors:
        print(line)
    print(f"check_links: {len(pages())} pages, {links} links, {len(errors)} broken"
          + (f", {len(warnings)} code paths not found" if args.code else ""))
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/python3
"""The documentation site: `mkdocs build --strict` from the repository's mkdocs.yml, failing on
any warning, on a page of docs/ left out of the navigation, and on a link of a built page to a
page, file or anchor that the site does not have.

Usage: check_site.py SOURCE_DIR WORK_DIR   (exit 0 good, 1 bad, 77 skipped: no mkdocs)
"""
import html.parser
import re
import shutil
import subprocess
import sys
import urllib.parse
from pathlib import Path

SKIP = 77


class Page(html.parser.HTMLParser):
    """A built page's element ids and the targets of its links."""

    def __init__(self):
        super().__init__()
        self.ids, self.links = set(), []

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if "id" in attrs:
            self.ids.add(attrs["id"])
        if tag == "a" and attrs.get("href"):
            self.links.append(attrs["href"])


def parse(page):
    p = Page()
    p.feed(page.read_text(encoding="utf-8"))
    return p


def main(source, work):
    if shutil.which("mkdocs") is None:
        print("skipped: mkdocs is not installed (scripts/install-deps installs Debian's mkdocs)")
        return SKIP
    site = work / "site"
    shutil.rmtree(site, ignore_errors=True)
    build = subprocess.run(["mkdocs", "build", "--strict", "--site-dir", str(site)], cwd=source,
                           capture_output=True, text=True)
    log = re.sub(r"\x1b\[[0-9;]*m", "", build.stdout + build.stderr)  # no colours
    problems = []
    if build.returncode != 0:
        problems.append(f"mkdocs build --strict: exit {build.returncode}")
    problems += [line for line in log.splitlines() if line.startswith(("WARNING", "ERROR"))]
    if "are not included in the \"nav\"" in log:
        problems.append("pages of docs/ not in mkdocs.yml's nav:\n" +
                        log.split("configuration:", 1)[1].split("INFO", 1)[0].rstrip())
    pages = {} if build.returncode else {p: parse(p) for p in site.rglob("*.html")}
    checked = 0
    for page, parsed in pages.items():
        for href in parsed.links:
            url = urllib.parse.urlsplit(href)
            if url.scheme or url.netloc or href.startswith("mailto:"):
                continue  # outside the site
            path = urllib.parse.unquote(url.path)
            base = site if path.startswith("/") else page.parent  # 404.html links from the root
            target = (base / path.lstrip("/")).resolve() if path else page
            if target.is_dir():
                target = target / "index.html"
            where = f"{page.relative_to(site)}: link {href!r}"
            if not target.exists():
                problems.append(f"{where}: no such file in the site")
            elif url.fragment and target.suffix == ".html":
                ids = pages[target].ids if target in pages else parse(target).ids
                if urllib.parse.unquote(url.fragment) not in ids:
                    problems.append(f"{where}: {target.relative_to(site)} has no anchor "
                                    f"#{url.fragment}")
            checked += 1
    if not problems and len(pages) < 2:
        problems.append(f"the site has {len(pages)} pages")
    for p in problems:
        print(p)
    print(f"{len(pages)} pages, {checked} links checked, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    sys.exit(main(Path(sys.argv[1]), Path(sys.argv[2])))

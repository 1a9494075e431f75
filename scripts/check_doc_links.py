#!/usr/bin/env python3
"""Every pointer into the documentation resolves: a citation `docs/PAGE.md, "Section"` (or
`PAGE.md, "Section"` within docs/) in the code, the scripts and the pages names a page that exists
and a heading of it (or a paragraph's bold opening words) that begins with the section's words,
backquotes aside; a markdown link to a file of the
repository ([text](path), relative to the page) names a file that exists; a page's `§n` citations of
docs/method.md name a numbered section of it. Headers' equations cite these pages, so a page
reorganised must keep its sections or change the citations with it.

Usage: scripts/check_doc_links.py [ROOT]
Exit status: 0 every pointer resolves, 1 one does not (each printed with its file and line).
"""
import os
import re
import sys

ROOT = os.path.abspath(sys.argv[1]) if len(sys.argv) > 1 else os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SOURCES = ('.cpp', '.hpp', '.py', '.sh', '.md', '.toml', '.cmake', '.txt', '.gp', '.pyi')
SKIP = {'build', '.git', 'results', 'node_modules'}
# docs/PAGE.md, "Section" — or PAGE.md, "Section" — with or without the comma.
CITATION = re.compile(r'(?:docs/)?([a-z0-9_]+\.md)\)?,? ["“]([^"”]+)["”]')
LINK = re.compile(r'\]\(([^)#\s]+)(?:#[^)]*)?\)')
SECTION = re.compile(r'method\.md §(\d+)')


def files():
    for dirpath, dirnames, names in os.walk(ROOT):
        dirnames[:] = [d for d in dirnames if d not in SKIP and not d.startswith('build')]
        for name in names:
            if name.endswith(SOURCES):
                yield os.path.join(dirpath, name)


def headings(page):
    path = os.path.join(ROOT, 'docs', page)
    if not os.path.isfile(path):
        return None
    titles = []
    with open(path, encoding='utf-8') as f:
        for line in f:
            if line.startswith('#'):
                titles.append(line.lstrip('#').strip().replace('`', ''))
            elif line.startswith('**'):  # a paragraph's bold opening words name it too
                titles.append(line[2:].split('**')[0].replace('`', ''))
    return titles


def main():
    cache, problems = {}, []
    method = headings('method.md') or []
    numbered = {m.group(1) for h in method for m in [re.match(r'(\d+)\.', h)] if m}
    for path in files():
        rel = os.path.relpath(path, ROOT)
        with open(path, encoding='utf-8', errors='replace') as f:
            lines = f.read().split('\n')
        for number, line in enumerate(lines, 1):
            for page, section in CITATION.findall(line):
                if page not in cache:
                    cache[page] = headings(page)
                titles = cache[page]
                if titles is None:
                    if os.path.isfile(os.path.join(ROOT, 'docs', page)) or page in ('README.md', 'changelog.md'):
                        continue
                    problems.append('%s:%d: docs/%s does not exist' % (rel, number, page))
                elif not any(t.startswith(section.replace('`', '')) for t in titles):
                    problems.append('%s:%d: docs/%s has no section "%s"' % (rel, number, page, section))
            if rel.endswith('.md'):
                for target in LINK.findall(line):
                    if re.match(r'[a-z]+:', target):
                        continue  # http:, https:, mailto:
                    if not os.path.exists(os.path.join(os.path.dirname(path), target)):
                        problems.append('%s:%d: link to %s, which does not exist' % (rel, number, target))
            for n in SECTION.findall(line):
                if n not in numbered:
                    problems.append('%s:%d: docs/method.md has no section %s' % (rel, number, n))
    for p in problems:
        print(p)
    print('%d pointers into the documentation do not resolve' % len(problems) if problems else
          'every pointer into the documentation resolves')
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main())

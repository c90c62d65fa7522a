#!/usr/bin/env python3
"""Checks docs/book.md, the index of the book's items, against the repository.

Every model file, source path and test the index names must exist (a test as `Suite.Name` after
its file: the file must define TEST(Suite, Name), TEST_F, TEST_P or TYPED_TEST); every validated
row names at least one test and its oracle, and its evidence does not admit that a part of the
result is not checked ("not run", "not compared", ...: that row is partial); every other row says
why; the summary's counts are the rows' counts, and the README quotes the totals.
Usage: book_index.py REPOSITORY_ROOT
"""
import collections
import pathlib
import re
import sys

STATUSES = ("validated", "partial", "modelled", "expressible", "not expressible")
# what a validated row's evidence may not say of a part of the book's result
UNCHECKED = re.compile(r"\bnot (?:run|used|compared|tested|computed|checked|modelled)\b")
PATH = re.compile(r"\b((?:models|tests|include|src|docs)/[\w./-]+\.(?:yaml|cpp|hpp|py|md))")
TEST_NAME = re.compile(r"`([A-Z]\w*)\.([A-Z]\w*)`")


def rows_of(text):
    """(section title, cells) of each row of the chapter tables."""
    section = None
    for line in text.splitlines():
        if line.startswith("## "):
            section = line[3:].strip()
        elif section and (section.startswith("Ch. ") or section.startswith("Appendix")):
            if line.startswith("| ") and not line.startswith("| id ") and not line.startswith("|---"):
                cells = [c.strip() for c in line.strip().strip("|").split(" | ")]
                yield section, cells


def summary_of(text):
    """The summary table: chapter → [items, and the count of each status]."""
    table = {}
    inside = False
    for line in text.splitlines():
        if line.startswith("## "):
            inside = line.strip() == "## Summary"
        elif inside and line.startswith("| ") and not line.startswith("| chapter"):
            cells = [c.strip().strip("*") for c in line.strip().strip("|").split(" | ")]
            table[cells[0]] = [int(c) for c in cells[1:]]
    return table


def tests_named(cell):
    """(file, suite, name) of each test a cell names: `Suite.Name` after its file's path."""
    current = None
    for m in re.finditer(r"(tests/[\w/]+\.cpp)|" + TEST_NAME.pattern, cell):
        if m.group(1):
            current = m.group(1)
        elif current:
            yield current, m.group(2), m.group(3)


def main(root):
    root = pathlib.Path(root)
    text = (root / "docs" / "book.md").read_text()
    errors = []
    counts = collections.defaultdict(collections.Counter)
    sources = {}
    for section, cells in rows_of(text):
        if len(cells) != 6:
            errors.append(f"{section}: a row without 6 cells: {cells[:1]}")
            continue
        item, status, oracle, evidence = cells[0], cells[3].split(" (")[0], cells[4], cells[5]
        # a | inside a cell ends the cell on GitHub: it is written \|
        if any(re.search(r"(?<!\\)\|", c) for c in cells):
            errors.append(f"{section} {item}: a cell holds an unescaped | (write \\|)")
        if status not in STATUSES:
            errors.append(f"{section} {item}: unknown status '{cells[3]}'")
            continue
        counts[section][status] += 1
        for path in PATH.findall(evidence):
            if not (root / path).exists():
                errors.append(f"{section} {item}: {path} does not exist")
        named = list(tests_named(evidence))
        for path, suite, name in named:
            if path not in sources:
                file = root / path
                sources[path] = file.read_text() if file.exists() else ""
            pattern = rf"\b(?:TEST|TEST_F|TEST_P|TYPED_TEST)\(\s*{suite},\s*{name}\s*\)"
            if not re.search(pattern, sources[path]):
                errors.append(f"{section} {item}: {path} has no test {suite}.{name}")
        if status == "validated" and not named:
            errors.append(f"{section} {item}: validated, but names no test")
        if status == "validated" and (not oracle or oracle.startswith("none")):
            errors.append(f"{section} {item}: validated, but names no oracle")
        if status == "validated" and UNCHECKED.search(evidence):
            errors.append(f"{section} {item}: validated, but its evidence says a part is "
                          f"'{UNCHECKED.search(evidence).group(0)}': partial")
        if status == "partial" and not named:
            errors.append(f"{section} {item}: partial, but names no test of the part it checks")
        if status != "validated" and len(evidence) < 8:
            errors.append(f"{section} {item}: {status}, but does not say why")
    summary = summary_of(text)
    total = collections.Counter()
    for section, counter in counts.items():
        total.update(counter)
        row = [sum(counter.values())] + [counter[s] for s in STATUSES]
        if summary.get(section) != row:
            errors.append(f"summary of {section}: {summary.get(section)}, the rows give {row}")
    all_row = [sum(total.values())] + [total[s] for s in STATUSES]
    if summary.get("all") != all_row:
        errors.append(f"summary of all: {summary.get('all')}, the rows give {all_row}")
    if len(summary) != len(counts) + 1:
        errors.append(f"the summary has {len(summary) - 1} chapters, the index {len(counts)}")
    # the README quotes the totals
    quoted = re.search(r"\((\d+) items: (\d+) validated, (\d+) partial\)",
                       (root / "README.md").read_text())
    if not quoted or [int(g) for g in quoted.groups()] != all_row[:3]:
        errors.append(f"README.md must say ({all_row[0]} items: {all_row[1]} validated, "
                      f"{all_row[2]} partial)")
    for e in errors:
        print(e)
    print(f"{all_row[0]} items, " + ", ".join(f"{n} {s}" for n, s in zip(all_row[1:], STATUSES)) +
          f"; {len(errors)} errors")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "."))

#!/usr/bin/env python3
"""The doc test: the commands shown in README.md and docs/*.md run, and docs/commands.md describes
every subcommand and option the command line has, so the docs cannot rot.

(a) Every line starting with `unidyn ` in a fenced ```sh block of README.md and docs/*.md is run
    with the built executable (no shell: split as the shell would, a `\\` at a line's end joining
    the next), each block in a fresh temporary directory of its own (with the repository's
    examples/ linked into it), in order; it must exit 0, or the status its comment names
    (`# exit 2: why`).
(b) `unidyn --help` and each subcommand's `--help`, nested ones too (`sweep plan`), give every
    subcommand and option; each must appear in docs/commands.md: a subcommand in a heading
    `unidyn <path>`, its options (`--xyz`) in that heading's section.
(c) Every relative link of README.md and docs/*.md names a file that exists.
(d) The ```python blocks of README.md and docs/python.md run with PYTHONPATH=BUILD/python when the
    module is built there (else a note says they were skipped).
Usage: docs_commands.py REPOSITORY_ROOT UNIDYN_EXECUTABLE [BUILD_DIRECTORY]
"""
import os
import pathlib
import re
import shlex
import subprocess
import sys
import tempfile
import time

FENCE = re.compile(r"^```(\w*)\s*$")
EXIT_MARK = re.compile(r"#\s*exit (\d+)\b")
OPTION = re.compile(r"(?<![\w-])(--[a-z][a-z0-9-]*)")
TIMEOUT = 120


def blocks(path, language):
    """(first line number, lines) of each fenced block of that language in a Markdown file."""
    found, inside, start, lines = [], None, 0, []
    for number, line in enumerate(path.read_text().splitlines(), 1):
        fence = FENCE.match(line)
        if fence and inside is None:
            inside, start, lines = fence.group(1), number + 1, []
        elif line.startswith("```") and inside is not None:
            if inside == language:
                found.append((start, lines))
            inside = None
        elif inside is not None:
            lines.append(line)
    return found


def commands_of(start, lines):
    """(line number, text) of each `unidyn ...` command of a block, continuation lines joined."""
    joined, number, text = [], None, ""
    for offset, line in enumerate(lines):
        if number is None:
            number, text = start + offset, line
        else:
            text = text[:-1] + " " + line.strip()
        if text.rstrip().endswith("\\"):
            text = text.rstrip()
            continue
        if text.startswith("unidyn "):
            joined.append((number, text))
        number = None
    return joined


def run_shown_commands(root, unidyn):
    """(a): each shown command exits as its documentation says; the failures' descriptions."""
    errors, count = [], 0
    for path in [root / "README.md"] + sorted((root / "docs").glob("*.md")):
        for start, lines in blocks(path, "sh"):
            shown = commands_of(start, lines)
            if not shown:
                continue
            with tempfile.TemporaryDirectory(prefix="unidyn-docs-") as directory:
                # the repository's examples/ (`unidyn import examples/urdf/...`) as a reader has them
                os.symlink(root / "examples", pathlib.Path(directory) / "examples")
                for number, text in shown:
                    mark = EXIT_MARK.search(text)
                    expected = int(mark.group(1)) if mark else 0
                    argv = [unidyn] + shlex.split(text, comments=True)[1:]
                    count += 1
                    try:
                        done = subprocess.run(argv, cwd=directory, capture_output=True, text=True,
                                              timeout=TIMEOUT)
                        status, err = done.returncode, done.stderr
                    except subprocess.TimeoutExpired:
                        status, err = "timeout", f"more than {TIMEOUT} s"
                    if status != expected:
                        errors.append(f"{path.relative_to(root)}:{number}: `{text}` exited "
                                      f"{status}, expected {expected}:\n    " +
                                      "\n    ".join(err.strip().splitlines()[-5:]))
    return errors, count


def help_of(unidyn, path):
    """The subcommands and options `unidyn PATH --help` lists."""
    text = subprocess.run([unidyn] + path + ["--help"], capture_output=True, text=True,
                          check=True).stdout
    subcommands, options, section = [], set(), None
    for line in text.splitlines():
        if line and not line.startswith(" "):
            section = line.rstrip(":")
        elif section == "Subcommands" and line.strip():
            subcommands.append(line.split()[0])
        elif section == "Options" and line.strip().startswith("-"):
            options.update(OPTION.findall(line.split("  ")[1] if line.startswith("  ") else line))
    options -= {"--help"}
    return subcommands, sorted(options)


def sections_of(text):
    """Heading → its section's text (up to the next heading of the same or a higher level)."""
    headings = [(m.start(), len(m.group(1)), m.group(2))
                for m in re.finditer(r"^(#+) (.*)$", text, re.MULTILINE)]
    sections = {}
    for k, (at, level, title) in enumerate(headings):
        end = next((a for a, lv, _ in headings[k + 1:] if lv <= level), len(text))
        sections[title] = text[at:end]
    return sections


def check_help_documented(root, unidyn):
    """(b): every subcommand and option of `--help` appears in docs/commands.md."""
    text = (root / "docs" / "commands.md").read_text()
    sections = sections_of(text)
    errors, count = [], 0
    subcommands, options = help_of(unidyn, [])
    for option in options + ["--help"]:
        count += 1
        if not re.search(re.escape(option) + r"(?![\w-])", text):
            errors.append(f"docs/commands.md does not mention `unidyn {option}`")
    pending = [[name] for name in subcommands]
    while pending:
        path = pending.pop(0)
        name = "unidyn " + " ".join(path)
        subcommands, options = help_of(unidyn, path)
        pending += [path + [sub] for sub in subcommands]
        count += 1
        # the section whose heading names the command (`unidyn linearize` and `unidyn modes`)
        own = [body for title, body in sections.items()
               if re.search(re.escape(name) + r"(?![\w-])", title)]
        if not own:
            errors.append(f"docs/commands.md has no heading naming `{name}`")
            continue
        for option in options:
            count += 1
            if not any(re.search(re.escape(option) + r"(?![\w-])", body) for body in own):
                errors.append(f"docs/commands.md does not mention `{name} {option}` in the "
                              f"section of `{name}`")
    return errors, count


def check_links(root):
    """(c): every relative link's file exists (anchors are not checked)."""
    errors = []
    for path in [root / "README.md"] + sorted((root / "docs").glob("*.md")):
        for target in re.findall(r"\]\(([^)#\s]+)(?:#[^)]*)?\)", path.read_text()):
            if "://" not in target and not (path.parent / target).exists():
                errors.append(f"{path.relative_to(root)}: the link to {target} leads nowhere")
    return errors


def run_python_blocks(root, build):
    """(d): the Python examples run; None when the module is not built."""
    module = pathlib.Path(build).resolve() / "python" if build else None
    if not module or not list((module / "unidyn").glob("_unidyn*.so")):
        return None, 0
    python = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable
    environment = dict(os.environ, PYTHONPATH=str(module))
    errors, count = [], 0
    for path in [root / "README.md", root / "docs" / "python.md"]:
        for start, lines in blocks(path, "python"):
            count += 1
            with tempfile.TemporaryDirectory(prefix="unidyn-docs-") as directory:
                # examples/ as a reader has it, as for the commands
                os.symlink(root / "examples", pathlib.Path(directory) / "examples")
                done = subprocess.run([python, "-c", "\n".join(lines)], cwd=directory,
                                      env=environment, capture_output=True, text=True,
                                      timeout=TIMEOUT)
            if done.returncode != 0:
                errors.append(f"{path.relative_to(root)}:{start}: the Python block failed:\n    " +
                              "\n    ".join(done.stderr.strip().splitlines()[-8:]))
    return errors, count


def main(root, unidyn, build=None):
    root, unidyn = pathlib.Path(root).resolve(), os.path.abspath(unidyn)
    began = time.monotonic()
    errors, shown = run_shown_commands(root, unidyn)
    help_errors, named = check_help_documented(root, unidyn)
    errors += help_errors + check_links(root)
    python_errors, python_blocks = run_python_blocks(root, build)
    if python_errors is None:
        print("note: the Python module is not built (no _unidyn in BUILD/python): "
              "the ```python blocks were not run")
    else:
        errors += python_errors
    for e in errors:
        print(e)
    print(f"{shown} commands shown run, {named} subcommands and options looked up in "
          f"docs/commands.md, {python_blocks} Python blocks run; {len(errors)} errors "
          f"({time.monotonic() - began:.1f} s)")
    return 1 if errors else 0


if __name__ == "__main__":
    if len(sys.argv) < 3:
        print(__doc__)
        sys.exit(2)
    sys.exit(main(*sys.argv[1:4]))

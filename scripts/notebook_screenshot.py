#!/usr/bin/env python3
"""Runs a notebook and takes a picture of it as Jupyter shows it: the README's screenshot
(docs/notebook-getting-started.png).

Usage: PYTHONPATH=build/python /usr/bin/python3 scripts/notebook_screenshot.py NOTEBOOK PNG [BUILD]

The notebook runs cell by cell in a Jupyter kernel (nbclient); its cells and outputs are laid out
on one page — the LaTeX by KaTeX (the report's own copy, BUILD/web/node_modules/katex), HTML as it
is, images inline — and headless Chromium photographs it. Offline: nothing is fetched.
"""

import base64
import html
import os
import pathlib
import subprocess
import sys
import tempfile

import nbclient
import nbformat


def output_html(output):
    """One output of a code cell as HTML."""
    data = output.get("data", {})
    if "image/png" in data:
        return f'<img src="data:image/png;base64,{data["image/png"]}">'
    if "text/html" in data:
        return data["text/html"]
    if "text/latex" in data:
        return f'<div class="latex">{html.escape(data["text/latex"])}</div>'
    text = data.get("text/plain") or output.get("text", "")
    return f"<pre class=\"out\">{html.escape(text)}</pre>" if text else ""


def page(notebook, katex):
    """The notebook as one HTML page."""
    parts = []
    for number, cell in enumerate(notebook.cells):
        if cell.cell_type == "markdown":
            parts.append(f'<div class="md">{html.escape(cell.source)}</div>')
            continue
        parts.append(f'<pre class="in"><b>[{cell.execution_count}]:</b> '
                     f"{html.escape(cell.source)}</pre>")
        parts.extend(output_html(o) for o in cell.outputs)
    style = ("body{font-family:sans-serif;max-width:960px;margin:16px auto;font-size:14px}"
             ".md{white-space:pre-wrap;margin:12px 0}.in{background:#f5f5f5;padding:8px;"
             "border-left:3px solid #42a5f5}.out{padding:4px 8px}img{max-width:600px}"
             "table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:2px 8px}"
             "iframe{height:520px !important}")
    script = ("for (const e of document.querySelectorAll('.latex')) katex.render("
              "e.textContent.replace(/\\\\begin\\{align\\}/g,'\\\\begin{aligned}')"
              ".replace(/\\\\end\\{align\\}/g,'\\\\end{aligned}').replace(/\\\\nonumber/g,''),"
              "e,{displayMode:true,throwOnError:false});")
    return (f"<!DOCTYPE html><html><head><meta charset=\"utf-8\"><link rel=\"stylesheet\" "
            f"href=\"{katex}/katex.min.css\"><script src=\"{katex}/katex.min.js\"></script>"
            f"<style>{style}</style></head><body>{''.join(parts)}<script>{script}</script>"
            "</body></html>")


def main(source, png, build="build"):
    os.environ.setdefault("PYDEVD_DISABLE_FILE_VALIDATION", "1")  # (ipykernel's debugger notes)
    notebook = nbformat.read(source, as_version=4)
    with tempfile.TemporaryDirectory() as scratch:
        nbclient.NotebookClient(notebook, timeout=600, kernel_name="python3",
                                resources={"metadata": {"path": scratch}}).execute()
        katex = pathlib.Path(build, "web", "node_modules", "katex", "dist").resolve().as_uri()
        shown = pathlib.Path(scratch, "notebook.html")
        shown.write_text(page(notebook, katex), encoding="utf-8")
        subprocess.run(["chromium", "--headless", "--no-sandbox", "--disable-gpu",
                        "--hide-scrollbars", f"--screenshot={os.path.abspath(png)}",
                        "--window-size=1000,1900", "--virtual-time-budget=8000",
                        shown.as_uri()], check=True, capture_output=True)


if __name__ == "__main__":
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    main(*sys.argv[1:])

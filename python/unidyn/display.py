"""How unidyn's results show themselves in a notebook (Jupyter Notebook and Lab, VS Code).

IPython asks an object for its richest form by the methods `_repr_latex_`, `_repr_html_` and
`_repr_markdown_`; the objects below give them and stay what they were otherwise (a derivation is
still its text, a linearisation still its dict). Everything is offline: a report is shown as its
own page in an iframe's `srcdoc`, with no server and no widget extension.
"""

import html
import os
import re
import tempfile


def _cell(value):
    """A table cell's text, escaped."""
    return html.escape(str(value))


def _table(header, rows):
    """A small HTML table: the header's cells, then each row's."""
    head = "".join(f"<th>{_cell(h)}</th>" for h in header)
    body = "".join("<tr>" + "".join(f"<td>{_cell(c)}</td>" for c in row) + "</tr>" for row in rows)
    return f"<table><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"


def _number(x):
    """A number as the tables print it: 12 significant digits."""
    return f"{x:.12g}" if isinstance(x, (int, float)) else str(x)


class Equations(str):
    """`derive()`'s text, a str as the command prints it; in a notebook, the equations in the
    book's form as LaTeX (`derive --format latex`, made when first shown: `latex` is a function
    giving it). The LaTeX's comment lines and \\label's are left out of what is shown (labels
    repeated in two cells would clash in the page's MathJax)."""

    def __new__(cls, text, latex=None):
        equations = super().__new__(cls, text)
        equations._latex = latex
        return equations

    def _repr_latex_(self):
        lines = [line for line in self._latex().splitlines() if not line.startswith("%")]
        return re.sub(r"\\label\{[^}]*\}", "", "\n".join(lines))


def model_html(name, coordinates, parameters, constraints):
    """A model as a small table: its name, coordinates, parameters with their values and
    constraints."""
    rows = [("coordinates", ", ".join(coordinates) or "none"),
            ("parameters", ", ".join(f"{k} = {_number(v)}" for k, v in parameters.items())
             or "none"),
            ("constraints", ", ".join(constraints) or "none")]
    return f"<strong>{_cell(name)}</strong>" + _table(("", ""), rows)


class Analysis(dict):
    """`linearize()`'s or `modes()`'s dict (`--format json`); in a notebook, its tables: the modes
    (eigenvalues, frequencies, damping) or Floquet multipliers and the verdict, and the state
    matrix A over the state."""

    def _repr_html_(self):
        parts = [f"<strong>{_cell(self.get('model', ''))}</strong>"]
        if "modes" in self:
            rows = [(_number(m["re"]), _number(m["im"]), _number(m["natural_frequency"]),
                     _number(m["damping_ratio"])) for m in self["modes"]]
            parts.append(_table(("Re λ", "Im λ", "natural frequency", "damping ratio"), rows))
        if "multipliers" in self:
            rows = [(_number(m["re"]), _number(m["im"]), _number(m["modulus"]))
                    for m in self["multipliers"]]
            parts.append(_table(("Re μ", "Im μ", "|μ|"), rows))
        if "stability" in self:
            parts.append(f"<p>stability: {_cell(self['stability'])}"
                         + (f" ({_cell(self['reason'])})" if self.get("reason") else "") + "</p>")
        if "A" in self and "state" in self:
            rows = [[name] + [_number(x) for x in row]
                    for name, row in zip(self["state"], self["A"])]
            parts.append("<p>A (ẋ = A x):</p>" + _table([""] + list(self["state"]), rows))
        return "".join(parts)


class Report(str):
    """`report()`'s line, a str as the command prints it; `.page` is the offline HTML page,
    `.save(path)` writes it, and in a notebook the page shows inline (an iframe whose `srcdoc` is
    the page: no server, no file)."""

    def __new__(cls, line, page=""):
        report = super().__new__(cls, line)
        report.page = page
        return report

    def save(self, path):
        """Writes the page to path, whole or not at all (a temporary file beside it, renamed)."""
        path = os.fspath(path)
        directory = os.path.dirname(os.path.abspath(path))
        handle, partial = tempfile.mkstemp(dir=directory, prefix=".unidyn-report-")
        try:
            with os.fdopen(handle, "w", encoding="utf-8") as out:
                out.write(self.page)
            os.replace(partial, path)
        except BaseException:
            os.unlink(partial)
            raise

    def _repr_html_(self):
        return ('<iframe style="width: 100%; height: 640px; border: 0" srcdoc="'
                + html.escape(self.page, quote=True) + '"></iframe>')


def plot(result, columns=None, ax=None):
    """The result's columns against t with matplotlib (Debian's python3-matplotlib): all but t
    unless `columns` names some; on `ax`, or on a new figure's axes. Returns the axes."""
    import matplotlib.pyplot as pyplot

    names = [c for c in result.columns if c != "t"] if columns is None else list(columns)
    if ax is None:
        _, ax = pyplot.subplots()
    for name in names:
        ax.plot(result.t, result[name], label=name)
    ax.set_xlabel("t")
    ax.legend()
    return ax

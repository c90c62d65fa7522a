"""unidyn from Python: models of mechanical systems, their equations of motion, runs and analyses.

    import unidyn
    top = unidyn.load("heavy-top")            # a bundled model, a model file, or a model's text
    print(top.derive())                       # Lagrange's equations as the book prints them
    run = top.simulate(t_end=5, set={"m": 2})
    run["theta"], run.t                       # numpy arrays, one per column
    run.to_pandas()                           # a DataFrame, when pandas is installed
    run.plot()                                # its columns against t (matplotlib)
    qdd, lam = top.rhs(q, qd)                 # one state, or an array of states (one per row)
    top.modes(at={"theta": 0.3, "der(psi)": 60})

Each method does what the `unidyn` command of the same name does, with the same options and checks.
A mistake in a model raises unidyn.ModelError (a ValueError) with .file, .line and .column; other
bad input raises ValueError; a failure RuntimeError. The work runs without the interpreter's lock
(other Python threads go on); unidyn's runs take turns between threads of one process (GiNaC is not
thread-safe), and `rhs` batches run in parallel: use processes for parallel runs (`sweep`).
"""

import functools
import json
import os
import tempfile

import numpy as np

# a package installed by `pip install .` carries the bundled models beside it (setup.py)
_MODELS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "share", "unidyn", "models")
if "UNIDYN_MODELS" not in os.environ and os.path.isdir(_MODELS):
    os.environ["UNIDYN_MODELS"] = _MODELS

from . import display  # noqa: E402 (after the models' place is known)
from ._unidyn import ModelError
from ._unidyn import Model as _Model

__all__ = ["load", "Model", "Result", "ModelError", "sweep", "SweepResult"]


def _settings(values):
    """{name: number} as [(name, float)], in the order given."""
    return [(str(k), float(v)) for k, v in (values or {}).items()]


def _points(values):
    """{name: value} as NAME=VALUE texts (a value may be an expression in the parameters)."""
    return [f"{k}={v}" for k, v in (values or {}).items()]


class Result:
    """A run: its columns as numpy arrays (result["name"], result.t), every row in .data, the
    summary `unidyn simulate` prints, the events (t, what), and whether it succeeded."""

    def __init__(self, columns, data, summary, events, ok, message):
        self.columns = list(columns)
        self.data = data
        self.summary = summary
        self.events = [(float(t), str(what)) for t, what in events]
        self.ok = bool(ok)
        self.message = message
        self._index = {name: k for k, name in enumerate(self.columns)}

    def __getitem__(self, name):
        if name not in self._index:
            raise KeyError(f"no column {name!r}; the columns are {', '.join(self.columns)}")
        return self.data[:, self._index[name]]

    def __len__(self):
        return self.data.shape[0]

    def __repr__(self):
        return f"<unidyn.Result: {len(self)} rows of {len(self.columns)} columns, {self.summary.splitlines()[0]}>"

    @property
    def t(self):
        return self["t"]

    def to_pandas(self):
        """The rows as a pandas DataFrame (pandas must be installed)."""
        import pandas

        return pandas.DataFrame(self.data, columns=self.columns)

    def plot(self, columns=None, ax=None):
        """Its columns against t with matplotlib: all of them unless `columns` names some; on
        `ax`, or on a new figure. Returns the axes."""
        return display.plot(self, columns, ax)


class Model:
    """A model: parameters, coordinates, constraints; its equations compiled once on first use
    (parameters are inputs of the compiled code: one compilation serves every parameter set)."""

    def __init__(self, source, limits=False):
        self._model = _Model(str(source), limits)
        self._set = {}  # parameters set by with_parameters

    def __reduce__(self):
        # to another process (an executor's worker) as its text and the parameters set: loaded
        # there once per process
        return (_loaded, (self.text, tuple(self._set.items())))

    def _with(self, set):
        """The settings of one call: the parameters set on the model, then the call's own."""
        return _settings({**self._set, **(set or {})})

    name = property(lambda self: self._model.name)
    reference = property(lambda self: self._model.reference)
    path = property(lambda self: self._model.path)
    text = property(lambda self: self._model.text)
    coordinates = property(lambda self: self._model.coordinates)
    constraints = property(lambda self: self._model.constraints)
    columns = property(lambda self: self._model.columns, doc="the columns of its runs")

    @property
    def parameters(self):
        """{name: value} as the model gives them."""
        return {**dict(self._model.parameters), **self._set}

    def __repr__(self):
        return f"<unidyn.Model {self.name!r}: {len(self.coordinates)} coordinates>"

    def with_parameters(self, **values):
        """The same model with parameters set by name, sharing its compiled equations: nothing is
        read or compiled again (parameters are inputs of the compiled code). A call's `set` still
        overrides them."""
        known = dict(self._model.parameters)
        unknown = sorted(set(values) - set(known))
        if unknown:
            raise ValueError(f"no parameter {', '.join(unknown)}; the parameters are "
                             f"{', '.join(known)}")
        other = object.__new__(Model)
        other._model = self._model
        other._set = {**self._set, **{str(k): float(v) for k, v in values.items()}}
        return other

    def to_yaml(self):
        """The model's text: the file or text it was read from, or the YAML made of the dict it
        was built from (load(dict))."""
        return self.text

    def _repr_html_(self):
        return display.model_html(self.name, self.coordinates, self.parameters, self.constraints)

    def derive(self, method="lagrange", format="text", form="textbook"):
        """`unidyn derive`: method lagrange | kane | newton-euler | second-form; format text |
        latex | json | c | python | matlab; form textbook | zees | matrix. The text as the
        command prints it; in text or LaTeX, a str that shows in a notebook as the book's LaTeX."""
        text = self._model.derive(method, format, form)
        if format == "text":
            latex = functools.partial(Model.derive, self, method, "latex", form)
            return display.Equations(text, latex)
        if format == "latex":
            return display.Equations(text, functools.partial(str, text))
        return text

    def simulate(self, t_end=None, output_step=None, method=None, rtol=None, set=None,
                 poses=False):
        """`unidyn simulate`: a Result. set: {name: number} of parameters, coordinates q and
        rates der(q); poses: each body's centre and Euler parameters, each particle's position."""
        return Result(*self._model._simulate(t_end, output_step, method, rtol, self._with(set),
                                             bool(poses)))

    def rhs(self, q, qd, t=0.0, set=None):
        """q'' and the multipliers lambda at (t, q, q') — q and qd of n values, or (count, n)
        arrays of states (one per row, evaluated without the interpreter's lock)."""
        return self._model.rhs(np.asarray(q, dtype=float), np.asarray(qd, dtype=float), float(t),
                               self._with(set))

    def linearize(self, at, set=None, period=None):
        """`unidyn linearize --format json`, as a dict. A driven system's point (equations that
        depend on t periodically, or period=T given) is a periodic motion: the dict has its
        "period", "A_at_t0" and "monodromy" in place of "A"."""
        return display.Analysis(json.loads(self._model._analysis(
            "linearize", _points(at), self._with(set), 0, [], _period(period))))

    def modes(self, at, set=None, period=None):
        """`unidyn modes --format json`, as a dict (eigenvalues, shapes, stability); for a
        periodic motion the Floquet "multipliers" (re, im, modulus, exponent_re, exponent_im)."""
        return display.Analysis(json.loads(self._model._analysis(
            "modes", _points(at), self._with(set), 0, [], _period(period))))

    def equilibria(self, at=None, set=None, starts=200, cyclic=()):
        """`unidyn equilibria --format json`, as a dict."""
        return json.loads(self._model._analysis("equilibria", _points(at), self._with(set),
                                                int(starts), list(cyclic)))

    def report(self, path=None, t_end=None, output_step=None, method=None, rtol=None, set=None):
        """`unidyn report`: the offline HTML page, written to `path` when one is given (`-o
        PATH`). Returns the line the command prints, a str carrying the page (`.page`,
        `.save(path)`) that shows it inline in a notebook."""
        with tempfile.TemporaryDirectory() as scratch:
            target = os.path.join(scratch, "report.html") if path is None else str(path)
            line = self._model._report(target, t_end, output_step, method, rtol, self._with(set))
            with open(target, encoding="utf-8") as page:
                text = page.read()
        if path is None:
            line = line.replace(f"written to {target}", "made (not saved: .save(path) writes it)")
        return display.Report(line, text)


def _period(period):
    """--period T, or None."""
    return None if period is None else float(period)


def load(source, limits=False):
    """A model from a file, a bundled model's name, a model's text, or a dict with the YAML's keys
    (made into YAML text, model.to_yaml(), and read as a text is: its mistakes are named by line
    and column of that text); `limits=True`: a URDF or MJCF file's joint limits as unilateral
    contacts (the commands' --limits)."""
    if isinstance(source, dict):
        source = _yaml_text(source)
    return Model(source, limits)


def _yaml_text(model):
    """A model given as a dict, as YAML text (PyYAML, Debian's python3-yaml; else JSON, which
    YAML reads): keys in the dict's order, numbers as Python writes them."""
    try:
        import yaml
    except ImportError:
        return json.dumps(model, indent=2, ensure_ascii=False) + "\n"
    return yaml.safe_dump(model, sort_keys=False, allow_unicode=True, default_flow_style=None)



@functools.lru_cache(maxsize=16)
def _loaded(text, parameters=()):
    """A model from its text, once per process (an executor's worker keeps it, compiled), with
    parameters set by name."""
    model = Model(text) if not parameters else _loaded(text)
    return model.with_parameters(**dict(parameters)) if parameters else model


def _kept(result, keep):
    """What a sweep keeps of one run: ("final",) its last row (NaN where it made none); ("all",)
    every row; ("times", ts) its rows at the times ts, which must be rows' times (the output
    step's multiples, to 1e-9 of the span: nothing is interpolated; a run that failed has none
    past its end); ("reduce", f) f(result),
    computed where the run is."""
    kind = keep[0]
    if kind == "final":
        return result.data[-1] if len(result) else np.full(len(result.columns), np.nan)
    if kind == "all":
        return result.data
    if kind == "times":
        t = result.t
        rows = []
        for wanted in keep[1]:
            k = int(np.argmin(np.abs(t - wanted))) if len(t) else -1
            if not result.ok and (k < 0 or wanted > t[-1]):
                break  # a run that failed before this time has no row there
            if k < 0 or abs(t[k] - wanted) > 1e-9 * max(1.0, abs(t[-1] - t[0])):
                raise ValueError(f"t = {wanted!r} is not the time of a row of this run (rows are "
                                 "at the output step's multiples, and where events fall): give "
                                 "times on that grid, or keep='all'")
            rows.append(result.data[k])
        return np.array(rows).reshape(len(rows), len(result.columns))
    return keep[1](result)


def _run_chunk(text, first, runs, options, parameters=(), keep=("final",)):
    """Runs (each a dict of settings) of the model given by its text and the parameters set on
    it: per run its index, whether it succeeded, what is kept of it (_kept), its events' count and
    why it failed. In whatever process runs it: only what is kept travels back."""
    model = _loaded(text, parameters)
    out = []
    for k, settings in enumerate(runs):
        try:
            result = model.simulate(set=settings, **options)
        except ValueError as error:  # a start that cannot be made: that run's failure
            out.append((first + k, False, None, 0, str(error)))
            continue
        # (a time that is not a row's is the caller's mistake: it stops the sweep)
        out.append((first + k, result.ok, _kept(result, keep), len(result.events),
                    result.message))
    return out


class SweepResult:
    """A sweep's runs in their order: the values set (.settings), whether each succeeded (.ok),
    its events' count (.events), why it failed (.messages), and what was kept of each (.kept):
    by default its last row — .final, a (runs, columns) array, NaN where a run made no row —;
    with keep="all" or times=[...] its rows (.rows, one (rows, columns) array per run, None where
    a run made none); with reduce=f the value f gave (.values). .to_pandas() is one tidy table:
    one row per run, or per run and time."""

    def __init__(self, names, columns, settings, rows, keep=("final",)):
        self.names, self.columns, self.settings = names, columns, settings
        self.keep = keep[0]
        self.ok = np.array([r[1] for r in rows], dtype=bool)
        self.kept = [r[2] for r in rows]
        self.events = np.array([r[3] for r in rows], dtype=int)
        self.messages = [r[4] for r in rows]
        if self.keep == "final":
            self.final = np.array([k if k is not None else np.full(len(columns), np.nan)
                                   for k in self.kept]).reshape(len(rows), len(columns))
        elif self.keep in ("all", "times"):
            self.rows = self.kept
        else:
            self.values = self.kept

    def __len__(self):
        return len(self.settings)

    def __getitem__(self, column):
        """The last value of a column in each run (keep="final")."""
        if self.keep != "final":
            raise KeyError(f"a column's last values are kept with keep='final' (this sweep kept "
                           f"{self.keep!r}: see .rows or .values)")
        return self.final[:, self.columns.index(column)]

    def to_pandas(self):
        """One table: the values set, ok, events and message of each run, with its last row
        (final.<column>) or its value (value); or one row per run and kept time, the values set
        as set.<name>, then the row's columns."""
        import pandas

        runs = pandas.DataFrame(self.settings, index=range(len(self)))
        runs.insert(0, "run", range(len(self)))
        runs["ok"], runs["events"], runs["message"] = self.ok, self.events, self.messages
        if self.keep == "final":
            for k, name in enumerate(self.columns):
                runs[f"final.{name}"] = self.final[:, k]
            return runs
        if self.keep == "reduce":
            runs["value"] = self.values
            return runs
        # per run and time: the values set as set.<name> (a coordinate's start and its value
        # at t are two columns), then the row
        runs = runs.rename(columns={name: f"set.{name}" for name in self.names})
        pieces = [pandas.DataFrame(rows, columns=self.columns).assign(run=k)
                  for k, rows in enumerate(self.rows) if rows is not None and len(rows)]
        if not pieces:
            return runs.iloc[0:0]
        return runs.merge(pandas.concat(pieces, ignore_index=True), on="run", how="inner")


def sweep(model, settings, executor=None, chunk=10, t_end=None, output_step=None, method=None,
          rtol=None, keep="final", times=None, reduce=None):
    """Runs the model once per entry of `settings` (each a {name: number} of parameters,
    coordinates q and rates der(q)), in chunks of `chunk` runs: in this process, or on any
    concurrent.futures executor or Dask distributed.Client (`executor.submit`). Each worker loads
    and compiles the model once. The result is the same, bit for bit, however the chunks were run;
    a chunk whose worker died is run again by the executor (Dask does so by itself), and each run
    appears once, in its place.

    What comes back of each run: keep="final" its last row (.final), keep="all" every row
    (.rows), times=[t1, ...] its rows at those times (rows' times: the output step's multiples),
    reduce=f whatever f(result) gives, computed on the worker (.values): a Monte Carlo of 10⁶ runs
    sends back only that."""
    if not isinstance(model, Model):
        model = load(model)
    settings = [dict(s) for s in settings]
    options = {"t_end": t_end, "output_step": output_step, "method": method, "rtol": rtol}
    chunk = max(1, int(chunk))
    parameters = tuple(model._set.items())  # set by with_parameters
    kept = _keep_spec(keep, times, reduce)
    pieces = [(first, settings[first:first + chunk]) for first in range(0, len(settings), chunk)]
    if executor is None:
        done = [_run_chunk(model.text, first, runs, options, parameters, kept)
                for first, runs in pieces]
    else:
        futures = [executor.submit(_run_chunk, model.text, first, runs, options, parameters, kept)
                   for first, runs in pieces]
        done = [future.result() for future in futures]
    rows = [row for piece in done for row in piece]
    if [r[0] for r in rows] != list(range(len(settings))):
        raise RuntimeError("the executor returned the runs out of order or not once each")
    names = sorted({name for s in settings for name in s})
    return SweepResult(names, model.columns, settings, rows, kept)


def _keep_spec(keep, times, reduce):
    """sweep's keep, times and reduce as one of _kept's specifications."""
    if sum(x is not None for x in (times, reduce)) + (keep != "final") > 1:
        raise ValueError("give one of keep='all', times=[...] and reduce=f")
    if times is not None:
        return ("times", tuple(float(t) for t in times))
    if reduce is not None:
        if not callable(reduce):
            raise ValueError("reduce must be a function of a run's Result")
        return ("reduce", reduce)
    if keep not in ("final", "all"):
        raise ValueError(f"keep must be 'final' or 'all', not {keep!r}")
    return (keep,)

"""Reading sluice output files (docs/output.md) with h5py and numpy."""
import csv
import math
import re

import numpy as np


def _text(v):
    """A string attribute as str (variable-length strings come as str,
    fixed-length ones of older files as bytes)."""
    if isinstance(v, bytes):
        return v.decode("utf-8")
    if isinstance(v, np.ndarray) and v.shape == ():
        return _text(v[()])
    return str(v)


_RESERVED = {"time", "index", "complete"}


class Output:
    """An output file OUT.h5, read-only. Only complete output times count
    (a run killed mid-step leaves one without the mark).

    times: the output times; steps: their group names; fields(): the field
    names of an output time; field(name, time=, step=): its values (n or
    n x 3); points(name): where they live (vertices, or cell centres for
    cell fields); units(name); scalars(): {name: array over the times};
    coordinates, cells, cell_centres, topology; provenance."""

    def __init__(self, path):
        import h5py

        self.path = path
        try:  # a running simulation holds the write lock: readers do not need it
            self._f = h5py.File(path, "r", locking=False)
        except TypeError:
            self._f = h5py.File(path, "r")
        steps = []
        for name, group in self._f.items():
            if re.fullmatch(r"step_\d+", name) and "complete" in group.attrs:
                steps.append((int(group.attrs["index"]), float(group.attrs["time"]), name))
        steps.sort()
        self.steps = [s[2] for s in steps]
        self.times = np.array([s[1] for s in steps])

    def close(self):
        self._f.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def _step(self, time=None, step=None):
        if not self.steps:
            raise KeyError(f"{self.path}: no complete output time")
        if step is not None:
            return self.steps[step]
        if time is None:
            return self.steps[-1]
        return self.steps[int(np.argmin(np.abs(self.times - time)))]

    def fields(self, time=None, step=None):
        """The field names of an output time (the last by default)."""
        return sorted(k for k in self._f[self._step(time, step)].keys())

    def field(self, name, time=None, step=None):
        """Field `name` at the output time nearest `time` (or the step-th,
        or the last): n values, or n x 3 for a vector."""
        group = self._f[self._step(time, step)]
        if name not in group:
            raise KeyError(f"{self.path}: no field '{name}' at {group.name} (fields: {', '.join(sorted(group))})")
        return group[name][()]

    def centring(self, name):
        """"node" or "cell"."""
        return _text(self._first_with(name).attrs["centring"])

    def units(self, name):
        """The unit of a field or a scalar ("" when not known)."""
        units = self.scalar_units
        if name in units:
            return units[name]
        return _text(self._first_with(name).attrs.get("units", ""))

    def _first_with(self, name):
        for s in reversed(self.steps):
            if name in self._f[s]:
                return self._f[s][name]
        raise KeyError(f"{self.path}: no field '{name}'")

    def points(self, name):
        """The coordinates (n x 3) where field `name` has its values."""
        return self.cell_centres if self.centring(name) == "cell" else self.coordinates

    @property
    def coordinates(self):
        return self._f["mesh/coordinates"][()]

    @property
    def cells(self):
        return self._f["mesh/topology"][()]

    @property
    def cell_centres(self):
        return self._f["mesh/cell_centres"][()]

    @property
    def topology(self):
        return _text(self._f["mesh/topology"].attrs["topology_type"])

    @property
    def scalar_units(self):
        if "scalar_units" not in self._f:
            return {}
        return {k: _text(v) for k, v in self._f["scalar_units"].attrs.items()}

    def scalars(self):
        """{name: numpy array over self.times}; NaN where an output time lacks it."""
        names = []
        for s in self.steps:
            for k in self._f[s].attrs:
                if k not in _RESERVED and k not in names:
                    names.append(k)
        out = {}
        for k in names:
            out[k] = np.array([float(self._f[s].attrs[k]) if k in self._f[s].attrs else math.nan for s in self.steps])
        return out

    @property
    def provenance(self):
        p = self._f["provenance"]
        d = {k: _text(v) for k, v in p.attrs.items()}
        d["ini"] = _text(p["ini"][()])
        return d


def read_scalars_csv(path):
    """OUT_scalars.csv as ({column: numpy array}, {column: unit}); the
    column names without their "[unit]"; empty cells are NaN."""
    with open(path, newline="", encoding="utf-8") as f:
        rows = list(csv.reader(f))
    names, units = [], {}
    for h in rows[0]:
        m = re.fullmatch(r"(.*?) \[(.*)\]", h)
        name = m.group(1) if m else h
        names.append(name)
        units[name] = m.group(2) if m else ""
    cols = {n: np.array([float(r[i]) if r[i] != "" else math.nan for r in rows[1:]]) for i, n in enumerate(names)}
    return cols, units

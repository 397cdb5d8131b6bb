"""Shared helpers of the paper scripts: read a verification driver's HDF5 output, save figures.

Every figure and table of paper/ is drawn from the files that the verification drivers write with
`--output` (verification/support/claim_check.cpp), so the figures and paper/REPORT.md show exactly
the numbers that `ctest -L verification` judged. Layout of one file:
  root attributes: driver, claim, scale (ci|full), passed, checks (JSON list of records
  {kind: check|report, what, ours, reference, detail, pass}), hmfnet_version, git_commit,
  wall_seconds, ranks, and the summed cost of the driver's accounted simulations (0 without
  any): force_evaluations, paper_evaluations, kernel_work, kernel_seconds, threads
  (verification/support/simulation_cost.hpp); datasets /data/NAME (1-D or 2-D) and string
  attributes of /data (notes).
A table's column names (or the names of a 1-D list of numbers) are the dataset's attribute
`columns`, a JSON list; scripts read columns by those names (DriverResult.table), never by
position, so a driver that reorders or adds a column cannot silently shift a figure's data.
"""
import argparse
import json
import os
import tempfile
from dataclasses import dataclass, field

import h5py
import matplotlib

matplotlib.use("Agg")  # no display on CI machines
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


@dataclass
class Table:
    """A /data dataset whose columns are named: table["K/K_c"] is that column of a 2-D table,
    or that number of a 1-D list of named numbers."""
    path: str
    name: str
    columns: list
    values: np.ndarray

    def __getitem__(self, column):
        if column not in self.columns:
            raise KeyError(f"{self.path}: dataset /data/{self.name} has no column '{column}' "
                           f"(columns: {self.columns})")
        i = self.columns.index(column)
        return self.values[i] if self.values.ndim == 1 else self.values[:, i]

    def __len__(self):
        return self.values.shape[0]


@dataclass
class DriverResult:
    driver: str
    claim: str
    scale: str
    passed: bool
    checks: list
    attrs: dict
    path: str = ""
    data: dict = field(default_factory=dict)
    columns: dict = field(default_factory=dict)  # dataset name -> its column names
    notes: dict = field(default_factory=dict)

    def series(self, name):
        """A /data dataset as a numpy array; KeyError names the driver and what it has."""
        if name not in self.data:
            raise KeyError(f"{self.driver}: no data series '{name}' (has: {sorted(self.data)})")
        return self.data[name]

    def table(self, name):
        """A /data dataset with named columns; KeyError names the file and the dataset."""
        values = self.series(name)
        if name not in self.columns:
            raise KeyError(f"{self.path}: dataset /data/{name} has no column names "
                           f"(attribute 'columns')")
        columns = self.columns[name]
        width = values.shape[-1] if values.ndim == 2 else values.size
        if values.ndim not in (1, 2) or len(columns) != width:
            raise ValueError(f"{self.path}: dataset /data/{name}: {len(columns)} column names "
                             f"for shape {values.shape}")
        return Table(self.path, name, columns, values)

    def note_json(self, name):
        return json.loads(self.notes[name])


def _text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def is_verification_output(path):
    """Whether PATH was written by a verification driver's --output (a data folder can also hold
    stored data that its own script draws, such as paper/full/beyond/data/qss_lifetime_gpu.h5)."""
    with h5py.File(path, "r") as f:
        return _text(f.attrs.get("hmfnet_format", "")) == "verification"


def load(data_dir, driver):
    """Reads DATA_DIR/DRIVER.h5 as written by `verification_DRIVER --output`."""
    path = os.path.join(data_dir, f"{driver}.h5")
    with h5py.File(path, "r") as f:
        attrs = {k: (_text(v) if isinstance(v, (bytes, str)) else v) for k, v in f.attrs.items()}
        if attrs.get("hmfnet_format") != "verification":
            raise ValueError(f"{path}: not a verification output (hmfnet_format missing)")
        result = DriverResult(
            driver=attrs["driver"], claim=attrs["claim"], scale=attrs["scale"],
            passed=bool(attrs["passed"]), checks=json.loads(attrs["checks"]), attrs=attrs,
            path=path)
        if "data" in f:
            for name, dataset in f["data"].items():
                result.data[name] = np.asarray(dataset[()])
                if "columns" in dataset.attrs:
                    result.columns[name] = json.loads(_text(dataset.attrs["columns"]))
            result.notes = {k: _text(v) for k, v in f["data"].attrs.items()}
    return result


def arguments(description):
    """The command line of every figure script: --data DIR (driver outputs), --out DIR."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--data", required=True, help="directory of the drivers' HDF5 outputs")
    parser.add_argument("--out", required=True, help="directory for NAME.png and NAME.pdf")
    return parser.parse_args()


def style():
    plt.rcParams.update({"figure.figsize": (9.0, 3.8), "font.size": 9, "axes.grid": True,
                         "grid.alpha": 0.3, "legend.fontsize": 7, "savefig.dpi": 130})


def save_figure(fig, out_dir, name, scale):
    """Writes NAME.png and NAME.pdf through temporaries renamed into place (no partial files)."""
    os.makedirs(out_dir, exist_ok=True)
    fig.text(0.995, 0.005, f"hmfnet, {scale} scale", ha="right", va="bottom", fontsize=6,
             color="0.5")
    for ext in ("png", "pdf"):
        final = os.path.join(out_dir, f"{name}.{ext}")
        fd, temp = tempfile.mkstemp(prefix=f".{name}.", suffix=f".{ext}", dir=out_dir)
        os.close(fd)
        try:
            fig.savefig(temp, format=ext, bbox_inches="tight")
            os.replace(temp, final)
        except BaseException:
            os.unlink(temp)
            raise
    plt.close(fig)


def write_text(path, text):
    """Atomic text output (markdown tables, the report)."""
    directory = os.path.dirname(os.path.abspath(path))
    os.makedirs(directory, exist_ok=True)
    fd, temp = tempfile.mkstemp(prefix=".tmp.", dir=directory)
    with os.fdopen(fd, "w") as f:
        f.write(text)
    os.replace(temp, path)

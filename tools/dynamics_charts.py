"""What the `gearstiff dynamics` charts share (plot_dynamics.py, plot_nonlinear_dynamics.py):
reading the command's CSV files with their "name [unit]" headers, the steady-state window band
and the common finish of a chart.

The plot scripts run as `python3 tools/plot_x.py ...`, so this module is found beside them on
sys.path. Importing it selects matplotlib's file backend (Agg).
"""
import csv

import matplotlib

matplotlib.use("Agg")
import chart_case  # noqa: E402,F401  (every figure names its case in a footer)
import matplotlib.pyplot as plt  # noqa: E402,F401  (re-exported to the plot scripts)


def read(path):
    """The CSV at `path` as (header, {header: [float or str, ...]}): numbers as floats ("nan"
    where a row has no valid value), a categorical column's names ("up", "valid") as str."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header = [h.strip() for h in rows[0]]
    columns = {h: [] for h in header}
    for row in rows[1:]:
        for h, v in zip(header, row):
            try:
                columns[h].append(float(v))
            except ValueError:
                columns[h].append(v)
    return header, columns


def column(header, columns, name):
    """The column called `name`, with or without its " [unit]"."""
    for h in header:
        if h == name or h.startswith(name + " ["):
            return columns[h]
    raise SystemExit(f"column {name} missing")


def shade_window(ax, window):
    """The steady-state window "START,END" [s] as a grey band."""
    start, end = (float(x) for x in window.split(",")[:2])
    ax.axvspan(start, end, color="0.9", zorder=0, label="steady-state window")


def finish(fig, ax, xlabel, ylabel, png, legend_at="best", legend_size=8):
    """Labels, grid and legend of a one-axes chart, then the PNG."""
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.grid(True, lw=0.3)
    ax.legend(loc=legend_at, fontsize=legend_size)
    fig.tight_layout()
    fig.savefig(png, dpi=120)

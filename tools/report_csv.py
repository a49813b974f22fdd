"""Reading the CSV tables that gearstiff commands write (header "name [unit]"; numbers, and the
names of a categorical column such as a sweep's direction).

Shared by the plot scripts in this folder; they run as `python3 tools/plot_x.py ...`, so this
module is found beside them on sys.path.
"""
import csv


def cell(text):
    """A number as float, a category's name as it is."""
    try:
        return float(text)
    except ValueError:
        return text


def read_table(path):
    """The table at `path` as {column name without its unit: [float or str, ...]}."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    names = [h.split(" [")[0] for h in rows[0]]
    return {n: [cell(r[i]) for r in rows[1:]] for i, n in enumerate(names)}

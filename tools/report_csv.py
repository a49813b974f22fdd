"""Reading the CSV tables that gearstiff commands write (header "name [unit]"; numbers, and the
names of a categorical column such as a sweep's direction), and the values and tables of their
JSON report (`--json` or summary.json: value(), column()).

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


def value(report, key):
    """values/<key> of a JSON report: the number (an entry with a unit is a dict)."""
    entry = report["values"][key]
    return entry["value"] if isinstance(entry, dict) else entry


def column(report, table, name):
    """Column `name` of table `table` of a JSON report (rows, or the "data" form)."""
    data = report["tables"][table]
    if "data" in data:
        return list(data["data"][name])
    index = data["columns"].index(name)
    return [row[index] for row in data["rows"]]

"""The Python module `gearstiff` (issue 32) against its oracle, the `gearstiff` command line.

Run by ctest (label python) with PYTHONPATH=build/python and GEARSTIFF_EXECUTABLE set, or by hand:
    PYTHONPATH=build/python GEARSTIFF_EXECUTABLE=build/app/gearstiff python3 -m pytest tests/python

- Every command runs in-process on its default case (the FE ones on a coarse scene).
- The fast commands' results equal `gearstiff <command> --json` to every printed digit: both come
  from the same Report, the CLI prints 12 significant digits (app/core/report.cc json_number), so
  '%.12g' of the module's double must be the CLI's text. Measured wall times are the only values
  that differ between two runs; they are named below and compared by unit only.
- Bad input raises gearstiff.InputError with the message the command line prints after
  "gearstiff: error: " (the dict is applied through the same `--set` code); a file not written
  whole raises OSError (issue 49).
"""
import json
import math
import os
import subprocess
import sys

import numpy as np
import pytest

import gearstiff

EXECUTABLE = os.environ.get("GEARSTIFF_EXECUTABLE", "gearstiff")
# The environment as the interpreter started: MPI, started by `import gearstiff`, may add
# variables to the C environment that would make a child process look launched by mpirun.
ENVIRONMENT = dict(os.environ)

# Values that are measured wall or CPU times, different in every run: (kind, table, column/key).
MEASURED_TIMES = {
    "gear-pair": {("value", None, "cost")},
    "kinematics": {("value", None, "cost")},
    "cycloid": {("column", "cycloid_correction", "solve_time")},
    "dynamics": {("value", None, "integration_time"), ("value", None, "integration_cpu_time"),
                 ("value", None, "sweep_time")},
}

# The overrides that keep an FE command short (the coarse scene of tests/cli/fuzz.py).
COARSE_MESH = {"contact size": 0.2, "fine radius": 0.5, "body size": 1, "rim size": 3}
COARSE_FE = {"Mesh": COARSE_MESH, "Finite elements": {"Element degree": 1}}


def cli(command, *arguments, check=True):
    """`gearstiff command arguments...`: (exit code, stdout, stderr)."""
    done = subprocess.run([EXECUTABLE, command, *arguments], capture_output=True, text=True,
                          timeout=240, env=ENVIRONMENT)
    if check and done.returncode != 0:
        raise AssertionError(f"gearstiff {command} failed: {done.stderr}")
    return done.returncode, done.stdout, done.stderr


def cli_json(command, *arguments):
    """The CLI's --json with every number kept as the text printed."""
    _, out, _ = cli(command, *arguments, "--json")
    return json.loads(out, parse_float=str, parse_int=str, parse_constant=str)


def printed(x):
    """A double as app/core/report.cc json_number prints it (std::setprecision(12), null for nan)."""
    return "null" if not math.isfinite(x) else "%.12g" % x


def assert_same_as_cli(result, expected, measured=()):
    assert result["command"] == expected["command"]
    assert result["text"] == expected["text"]
    assert list(result["values"]) == list(expected["values"])
    compared = 0
    for key, entry in expected["values"].items():
        mine = result["values"][key]
        assert set(mine) == set(entry), key
        for field, text in entry.items():
            if field in ("value", "published", "relative_deviation"):
                if ("value", None, key) in measured:
                    continue
                got = None if text is None else printed(mine[field])
                assert got == (text if text is not None else None), (key, field, mine[field], text)
                compared += 1
            else:
                assert mine[field] == text, (key, field)
    assert list(result["tables"]) == list(expected["tables"])
    for name, table in expected["tables"].items():
        mine = result["tables"][name]
        assert mine["columns"] == table["columns"]
        assert [mine["units"][c] for c in mine["columns"]] == table["units"]
        assert mine["categories"] == table.get("categories", {})
        for c, column in enumerate(table["columns"]):
            data = mine["data"][column]
            assert isinstance(data, np.ndarray) and len(data) == len(table["rows"])
            if column in mine["categories"]:  # names, as in the CLI's JSON and CSV
                assert data.dtype.kind == "U"
                assert list(data) == [row[c] for row in table["rows"]], (name, column)
                compared += len(data)
                continue
            assert data.dtype == np.float64
            if ("column", name, column) in measured:
                continue
            for r, row in enumerate(table["rows"]):
                text = row[c] if row[c] is not None else "null"
                assert printed(data[r]) == text, (name, column, r, data[r], text)
                compared += 1
    assert result["files"] == expected["files"]
    return compared


# ------------------------------------------------------------------ the fast commands, exactly

@pytest.mark.parametrize("command", ["gear-pair", "kinematics", "cycloid", "dynamics"])
def test_default_case_equals_command_line(command):
    function = getattr(gearstiff, command.replace("-", "_"))
    result = function()
    compared = assert_same_as_cli(result, cli_json(command), MEASURED_TIMES[command])
    assert compared >= 20  # every command reports far more; a vacuous comparison fails
    # The parameters used are the command line's parameters.json, and reproduce the run.
    assert result["timings"]["run"] > 0 and result["timings"]["total"] >= result["timings"]["run"]
    again = function(result["parameters"])
    assert_same_as_cli(again, cli_json(command), MEASURED_TIMES[command])


def test_dict_equals_set_and_prm_file(tmp_path):
    params = {"Gear pair": {"Pinion": {"face width": 30, "profile shift": 0.25},
                            "Wheel": {"profile shift": -0.25}}}
    result = gearstiff.gear_pair(params)
    sets = ["--set", "Gear pair/Pinion/face width=30", "--set", "Gear pair/Pinion/profile shift=0.25",
            "--set", "Gear pair/Wheel/profile shift=-0.25"]
    assert_same_as_cli(result, cli_json("gear-pair", *sets), MEASURED_TIMES["gear-pair"])
    assert result["parameters"]["Gear pair"]["Pinion"]["face width"] == 30.0
    # The same as a .prm file (str and pathlib.Path) and as the .json the module returned.
    prm = tmp_path / "pair.prm"
    prm.write_text("subsection Gear pair\n  subsection Pinion\n    set face width = 30\n"
                   "    set profile shift = 0.25\n  end\n  subsection Wheel\n"
                   "    set profile shift = -0.25\n  end\nend\n")
    for path in (str(prm), prm):
        assert_same_as_cli(gearstiff.gear_pair(path), cli_json("gear-pair", str(prm)),
                           MEASURED_TIMES["gear-pair"])
    # (The parameters.json the command line writes reads back too since session 49: deal.II 9.4
    # read a name holding '_', ISO 6336/C_M, as mangled; tests/cli/parameters_round_trip.py.)
    # The keys as `--set` spells them (a new user's first try, session 19), flat or mixed.
    flat = {"Gear pair/Pinion/face width": 30, "Gear pair/Pinion/profile shift": 0.25,
            "Gear pair": {"Wheel/profile shift": -0.25}}
    assert_same_as_cli(gearstiff.gear_pair(flat), cli_json("gear-pair", *sets),
                       MEASURED_TIMES["gear-pair"])


def test_types_of_values():
    # bool, int, float, numpy scalars and lists become the .prm text the CLI would be given.
    a = gearstiff.gear_pair({"Gear pair": {"Pinion": {"face width": np.int64(30),
                                                      "profile shift": np.float64(0.25)}}})
    b = gearstiff.gear_pair({"Gear pair": {"Pinion": {"face width": "30", "profile shift": "0.25"}}})
    assert a["values"]["centre_distance"]["value"] == b["values"]["centre_distance"]["value"]
    assert a["parameters"] == b["parameters"]
    r = gearstiff.stiffness({**COARSE_FE, "Stiffness": {"mode": "single", "published reference": False}})
    assert r["parameters"]["Stiffness"]["published reference"] is False


def test_parameters_are_numbers():
    # The parameters used come back typed by their patterns (were all str: '23'), and a later
    # call takes them back.
    p = gearstiff.gear_pair({"Gear pair": {"Pinion": {"teeth": 23}}})["parameters"]
    pinion = p["Gear pair"]["Pinion"]
    assert pinion["teeth"] == 23 and isinstance(pinion["teeth"], int)
    assert isinstance(pinion["profile shift"], float)
    assert gearstiff.gear_pair(p)["parameters"] == p


def test_version():
    assert isinstance(gearstiff.__version__, str)
    assert [part.isdigit() for part in gearstiff.__version__.split(".")] == [True] * 3
    assert gearstiff.__version__ in gearstiff.__doc__


def test_import_fails_clearly_without_numpy():
    # NumPy hidden (sys.modules entry None makes `import numpy` fail): the import of gearstiff
    # fails at once naming NumPy, not at the first call.
    done = subprocess.run([sys.executable, "-c", "import sys; sys.modules['numpy'] = None; "
                           "import gearstiff"], capture_output=True, text=True, env=ENVIRONMENT)
    assert done.returncode != 0
    assert "ImportError: gearstiff needs NumPy" in done.stderr, done.stderr


def test_misspelt_selection_value():
    # A value a selection does not allow is answered with the nearest allowed one, on the
    # command line and in Python alike.
    code, _, err = cli("stiffness", "--set", "Stiffness/mode=swep", check=False)
    assert code == 2
    assert "did you mean 'sweep'?" in err
    with pytest.raises(gearstiff.InputError) as raised:
        gearstiff.stiffness({"Stiffness": {"mode": "swep"}})
    assert "gearstiff: error: " + str(raised.value) == err.strip()
    assert str(raised.value) == ("Stiffness/mode: cannot set to 'swep': not one of 'single', "
                                 "'double', 'roll angle', 'sweep'; did you mean 'sweep'?")


# ------------------------------------------------------------------ every command runs

FE_CASES = {
    "mesh": {"Mesh": COARSE_MESH},
    "stiffness": {**COARSE_FE, "Stiffness": {"published reference": False}},
    "cai": {**COARSE_FE, "Stiffness": {"sweep positions": 5}},
    "run": {**COARSE_FE, "Stiffness": {"sweep positions": 5}},
    "contact": {"Mesh": {"Built-in fine size": 0.05}},
    "cycloid_loads": {"Mesh": {"contact size": 0.3, "fine radius": 0.6},
                      "Cycloid loads": {"profiles": "nominal", "torsional curve": False}},
}


def settings(params):
    """A parameter dict as the command line's --set arguments."""
    arguments = []
    for section, entries in params.items():
        for key, value in entries.items():
            text = str(value).lower() if isinstance(value, bool) else str(value)
            arguments += ["--set", f"{section}/{key}={text}"]
    return arguments


def wall_times(expected):
    """The values and columns in seconds of a CLI JSON: wall and CPU times of this run (and, for
    FE commands, every other entry in s, e.g. a time step, is left out with them)."""
    measured = {("value", None, key) for key, entry in expected["values"].items()
                if entry.get("unit") == "s"}
    for name, table in expected["tables"].items():
        measured |= {("column", name, column)
                     for column, unit in zip(table["columns"], table["units"]) if unit == "s"}
    return measured


@pytest.mark.parametrize("command", sorted(FE_CASES))
def test_every_fe_command_runs(command, capfd):
    # The command line is the oracle (issue 43): every number the module returns for the coarse
    # case is the one `gearstiff <command> --set ... --json` prints, to its 12 printed digits
    # (one code path, deterministic solvers), wall times aside.
    result = getattr(gearstiff, command)(FE_CASES[command])
    assert result["command"] == command.replace("_", "-")
    assert result["values"], "an FE command reports values"
    for table in result["tables"].values():
        lengths = {len(column) for column in table["data"].values()}
        assert len(lengths) == 1 and set(table["units"]) == set(table["columns"])
    out, err = capfd.readouterr()
    assert out == "" and err == "", "nothing is printed unless verbose=True"
    expected = cli_json(command.replace("_", "-"), *settings(FE_CASES[command]))
    assert assert_same_as_cli(result, expected, wall_times(expected)) >= 5


def test_every_command_has_a_function():
    names = {name.replace("-", "_") for name in gearstiff.commands()}
    assert names >= {"gear_pair", "stiffness", "cai", "dynamics", "kinematics", "cycloid",
                     "cycloid_loads", "mesh", "contact", "run", "faults"}
    for name in names:
        assert callable(getattr(gearstiff, name))
        assert name in gearstiff.__doc__  # help(gearstiff) lists every command


def test_quiet_and_verbose(capfd):
    params = {**COARSE_FE, "Stiffness": {"mode": "single", "published reference": False}}
    quiet = gearstiff.stiffness(params)
    out, err = capfd.readouterr()
    assert out == "" and err == ""
    loud = gearstiff.stiffness(params, verbose=True)
    out, err = capfd.readouterr()
    assert out != ""  # progress lines
    key = "mesh_stiffness"
    assert key in quiet["values"]
    assert quiet["values"][key]["value"] == loud["values"][key]["value"]


def test_output_directory(tmp_path):
    result = gearstiff.gear_pair(output_directory=tmp_path / "out")
    written = sorted(os.listdir(tmp_path / "out"))
    assert "summary.json" in written and "parameters.prm" in written
    assert sorted(result["files"]) == sorted(f for f in written)
    # A failing run leaves nothing, as on the command line.
    with pytest.raises(gearstiff.InputError):
        gearstiff.gear_pair({"Gear pair": {"Pinion": {"teeth": 2}}},
                            output_directory=tmp_path / "bad")
    assert not (tmp_path / "bad").exists()
    assert [p for p in os.listdir(tmp_path) if p.startswith(".gearstiff-staging")] == []


def test_results_name_the_code_that_produced_them(tmp_path):
    """A result file says which gearstiff wrote it: summary.json, --json, the Python result and
    parameters.prm carry the version and source revision `gearstiff --version` prints."""
    result = gearstiff.gear_pair(output_directory=tmp_path / "out")
    info = result["gearstiff"]
    assert info["version"] == gearstiff.__version__
    assert info["revision"] == gearstiff.__revision__ and info["revision"]
    assert info["libraries"]["deal.II"].startswith("9.")
    assert set(info["libraries"]) == {"deal.II", "PETSc", "gmsh", "Eigen"}
    with open(tmp_path / "out" / "summary.json") as f:
        assert json.load(f)["gearstiff"] == info
    assert cli_json("gear-pair")["gearstiff"] == info
    with open(tmp_path / "out" / "parameters.prm") as f:
        first = f.readline()
    assert first.startswith("# The parameters `gearstiff gear-pair` used; gearstiff "
                            f"{info['version']} (revision {info['revision']})"), first
    done = subprocess.run([EXECUTABLE, "--version"], capture_output=True, text=True, timeout=60,
                          env=ENVIRONMENT)
    assert done.returncode == 0 and done.stderr == "", done.stderr
    lines = done.stdout.splitlines()
    assert lines[0] == f"gearstiff {info['version']} (revision {info['revision']})"
    assert lines[1] == "built against " + ", ".join(
        f"{name} {version}" for name, version in info["libraries"].items())
    assert lines[2].startswith("MPI: ") and len(lines) == 3


# ------------------------------------------------------------------ errors

# (command, dict, the same as --set): each must raise InputError with the CLI's message.
BAD_VALUES = [
    ("gear-pair", {"Gear pair": {"Pinion": {"teeth": 2}}}, "Gear pair/Pinion/teeth=2"),
    ("gear-pair", {"Gear pair": {"Pinion": {"teeth": "many"}}}, "Gear pair/Pinion/teeth=many"),
    ("gear-pair", {"Gear pair": {"Pinion": {"profile shift": 3.0}}},
     "Gear pair/Pinion/profile shift=3.0"),
    ("gear-pair", {"Gear pair": {"Pinion": {"teeth": 1.5}}}, "Gear pair/Pinion/teeth=1.5"),
    ("dynamics", {"Simulation": {"simulated time": -1}}, "Simulation/simulated time=-1"),
    ("cycloid", {"Cycloid disc": {"rollers": 2}}, "Cycloid disc/rollers=2"),
    ("kinematics", {"Train": {"input torque": "abc"}}, "Train/input torque=abc"),
    # issue 42: an int beyond any C++ integer is range-checked before the cast.
    ("faults", {"Gear pair": {"Pinion": {"faulty tooth": 10 ** 30}}},
     "Gear pair/Pinion/faulty tooth=" + str(10 ** 30)),
]


@pytest.mark.parametrize("command,params,setting", BAD_VALUES)
def test_bad_input_same_message_as_command_line(command, params, setting):
    code, _, err = cli(command, "--set", setting, check=False)
    assert code == 2, err
    with pytest.raises(gearstiff.InputError) as raised:
        getattr(gearstiff, command.replace("-", "_"))(params)
    assert "gearstiff: error: " + str(raised.value) == err.strip()
    assert isinstance(raised.value, ValueError)
    assert str(raised.value).startswith(raised.value.parameter + ":")


@pytest.mark.parametrize("name,reason", [
    ("", "names no file or folder"),
    ("n" * 300, "a name in the path has 300 characters"),
])
def test_output_directory_names(tmp_path, name, reason):
    """Issue 42: "" wrote nothing, a name beyond NAME_MAX raised std::filesystem's RuntimeError."""
    folder = name if name == "" else str(tmp_path / name)
    with pytest.raises(gearstiff.InputError) as raised:
        gearstiff.gear_pair(output_directory=folder)
    assert raised.value.parameter == "output_directory"
    assert reason in str(raised.value)


def test_missing_parameter_file_same_message(tmp_path):
    missing = str(tmp_path / "nothing.prm")
    _, _, err = cli("gear-pair", missing, check=False)
    with pytest.raises(gearstiff.InputError) as raised:
        gearstiff.gear_pair(missing)
    assert "gearstiff: error: " + str(raised.value) == err.strip()


@pytest.mark.parametrize("params,parameter,hint", [
    ({"Gear pair": {"Pinion": {"teth": 21}}}, "Gear pair/Pinion/teth", "did you mean 'teeth'?"),
    ({"Gear pairs": {}}, "Gear pairs", "did you mean 'Gear pair'?"),
    ({"Gear pair": {"pinion": {"teeth": 21}}}, "Gear pair/pinion", "did you mean 'Pinion'?"),
    ({"Gear pair": {"Pinion": {"zzzzzzzzzzzzzzzzzz": 1}}}, "Gear pair/Pinion/zzzzzzzzzzzzzzzzzz",
     "the names here are 'addendum coefficient', 'bore diameter'"),
    ({"Gear pair": {"Pinion": {"teeth": {"value": 21}}}}, "Gear pair/Pinion/teeth",
     "expects a value, got a dict"),
    ({"Gear pair": {"Pinion": 21}}, "Gear pair/Pinion", "is a subsection"),
    ({"Gear pair": {"Pinion": {"teeth": None}}}, "Gear pair/Pinion/teeth", "got None"),
    ({"Gear pair": {"Pinion": {"teeth": [[21]]}}}, "Gear pair/Pinion/teeth", "nested list"),
    ({"Gear pair": {"Pinion": {1: 21}}}, "Gear pair/Pinion", "names must be strings"),
    ({"Gear pair/Pinion/teth": 21}, "Gear pair/Pinion/teth", "did you mean 'teeth'?"),
    ({"Gear pair/Pinion": 21}, "Gear pair/Pinion", "is a subsection"),
])
def test_bad_names_and_types(params, parameter, hint):
    with pytest.raises(gearstiff.InputError) as raised:
        gearstiff.gear_pair(params)
    assert raised.value.parameter == parameter
    assert str(raised.value).startswith(parameter + ": ")
    assert hint in str(raised.value)


def test_params_of_wrong_kind():
    with pytest.raises(gearstiff.InputError, match="^params: expects a dict"):
        gearstiff.gear_pair(42)


def test_solver_failure_is_raised():
    # RK4 above its stability limit, allowed to run (tests/dynamics/CMakeLists.txt
    # dynamics_diverges): the command line exits 3 naming RK4; the module raises SolverFailure
    # with the same message.
    settings = {"Speed sweep": {"points": 0},
                "Simulation": {"time step": 60, "allow unstable step": True}}
    code, _, err = cli("dynamics", "--set", "Speed sweep/points=0", "--set",
                       "Simulation/time step=60", "--set", "Simulation/allow unstable step=true",
                       check=False)
    assert code == 3, err
    with pytest.raises(gearstiff.SolverFailure) as raised:
        gearstiff.dynamics(settings)
    # The last line: progress lines ("dynamics: simulating ...") come first on stderr.
    assert "gearstiff: solver failure: " + str(raised.value) == err.strip().splitlines()[-1]
    assert raised.value.method == "RK4"
    assert isinstance(raised.value, RuntimeError)


def test_failed_write_is_os_error(tmp_path):
    # Issue 49: a chart beyond the file-size limit (the case of tests/cli/faults.py: charts of
    # 68 kB and more, files within 48.4 kB, measured 2026-12-01) raises OSError with the command
    # line's message after "gearstiff: I/O error: ", and nothing is left in -o. Python ignores
    # SIGXFSZ itself, so the write fails with EFBIG here as it does in `gearstiff`.
    import resource
    out = tmp_path / "out"
    settings = {"Simulation": {"output interval": 2000}}
    limit = resource.getrlimit(resource.RLIMIT_FSIZE)
    resource.setrlimit(resource.RLIMIT_FSIZE, (56 * 1024, limit[1]))
    try:
        with pytest.raises(OSError) as raised:
            gearstiff.dynamics(settings, output_directory=out)
    finally:
        resource.setrlimit(resource.RLIMIT_FSIZE, limit)
    assert str(raised.value).startswith(f"-o {out}: cannot write 'dynamics_"), raised.value
    assert str(raised.value).endswith("': file size limit reached (ulimit -f: 56 kB per file)")
    assert not out.exists()
    assert [p for p in os.listdir(tmp_path) if p.startswith(".gearstiff-staging")] == []


@pytest.mark.parametrize("kind", ["file", "missing"])
def test_tmpdir_not_a_folder_same_message(tmp_path, kind):
    """Issue 42: TMPDIR naming a file (or nothing) is gearstiff.InputError naming TMPDIR, with
    the command line's message and exit 2 there, and nothing written."""
    target = tmp_path / "a_file"
    if kind == "file":
        target.write_text("not a folder")
    out = tmp_path / "out"
    environment = dict(ENVIRONMENT, TMPDIR=str(target))
    done = subprocess.run([EXECUTABLE, "gear-pair", "-o", str(out)], capture_output=True,
                          text=True, timeout=60, env=environment)
    assert done.returncode == 2, done.stderr
    saved = os.environ.get("TMPDIR")
    os.environ["TMPDIR"] = str(target)
    try:
        with pytest.raises(gearstiff.InputError) as raised:
            gearstiff.gear_pair(output_directory=out)
    finally:
        if saved is None:
            del os.environ["TMPDIR"]
        else:
            os.environ["TMPDIR"] = saved
    assert raised.value.parameter == "TMPDIR"
    assert "gearstiff: error: " + str(raised.value) == done.stderr.strip()
    assert "is not a folder" in str(raised.value)
    assert not out.exists()


@pytest.mark.parametrize("script,default", [("optimise_tip_relief.py", "(default: 400.0)"),
                                            ("design_pinion_bore.py", "(default: pinion_bore.png)")])
def test_examples_take_a_pair_file_and_show_defaults(tmp_path, script, default):
    """Issue 44: the examples ran the built-in pair only and their --help showed no defaults."""
    path = os.path.join(os.path.dirname(__file__), "..", "..", "examples", script)
    done = subprocess.run([sys.executable, path, "--help"], capture_output=True, text=True,
                          timeout=120, env=ENVIRONMENT)
    assert done.returncode == 0, done.stderr
    assert default in " ".join(done.stdout.split()), done.stdout
    assert "your pair's .prm file" in done.stdout
    missing = str(tmp_path / "nothing.prm")
    done = subprocess.run([sys.executable, path, missing], capture_output=True, text=True,
                          timeout=120, env=ENVIRONMENT)
    assert done.returncode == 1 and missing in done.stderr, done.stderr


# ------------------------------------------------------------------ print_parameters

def test_print_parameters():
    p = gearstiff.print_parameters("gear_pair")
    teeth = p["Gear pair"]["Pinion"]["teeth"]
    assert teeth["default"] == 21 and isinstance(teeth["default"], int)
    assert "Integer" in teeth["allowed"]
    shift = p["Gear pair"]["Pinion"]["profile shift"]
    assert isinstance(shift["default"], float)
    assert gearstiff.print_parameters("gear-pair") == p
    # Units from the documentation strings, where stated.
    units = [e["unit"] for e in p["Gear pair"]["Pinion"].values() if isinstance(e, dict)
             and "unit" in e and e["unit"]]
    assert "mm" in units
    # The defaults, as a dict, are a valid input giving the default result.
    defaults = {"Gear pair": {"Pinion": {"teeth": teeth["default"]}}}
    assert gearstiff.gear_pair(defaults)["values"]["centre_distance"]["value"] == \
        gearstiff.gear_pair()["values"]["centre_distance"]["value"]
    with pytest.raises(gearstiff.InputError, match="unknown command"):
        gearstiff.print_parameters("frobnicate")


def test_input_notes_are_warnings(tmp_path, capfd):
    # A pair file shared with other commands: the command line notes on stderr that `gear-pair`
    # ignores the scene's torque; the module raises the same note as a UserWarning and prints
    # nothing (README: nothing is printed unless verbose=True).
    pair = tmp_path / "pair.prm"
    pair.write_text("subsection Gear pair\n  subsection Pinion\n    set teeth = 23\n  end\nend\n"
                    "subsection Gear pair scene\n  set pinion torque = 300\nend\n")
    with pytest.warns(UserWarning, match="other commands use ignored by `gear-pair`"):
        gearstiff.gear_pair(str(pair))
    out, err = capfd.readouterr()
    assert out == "" and err == ""

// The Python module `gearstiff`: every command of the command line as a function that runs in
// the calling process and returns its report as a dict with NumPy arrays.
//
//   import gearstiff                                   # PYTHONPATH=build/python
//   r = gearstiff.gear_pair({"Gear pair": {"Pinion": {"teeth": 21}}})
//   r["values"]["transverse_contact_ratio"]["value"]; r["tables"]["contact_zones"]["data"]["start"]
//
// A command runs through the same functions as `gearstiff <command>` (app/core/invoke.h): a nested
// dict becomes the `--set section/key=value` overrides of the command line, a str/path is the
// parameter file, and the result is built from the same Report that `--json` prints. Errors are
// the command line's: gearstiff.InputError (a ValueError) and gearstiff.SolverFailure (a
// RuntimeError) with the message the command line prints after "gearstiff: error: "; a file not
// written whole (a full disk) is an OSError with the command line's "I/O error" message.
//
// MPI: the module initialises MPI (and PETSc) on import unless it is running already, and
// finalises what it started at interpreter exit. Under `mpirun -np N python3 script.py` every
// rank calls the same functions and a sweep is distributed over the ranks as by the command line.
#include "app/core/build_info.h"
#include "app/core/command.h"
#include "app/core/invoke.h"
#include "app/core/report.h"
#include "app/core/scratch.h"
#include "app/core/units.h"
#include "errors/errors.h"
#include "errors/file_names.h"
#include "fem/blas_start.h"
#include "fem/mpi_start.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdlib>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <dlfcn.h>
#include <memory>
#include <petscsys.h>
#include <pybind11/iostream.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <sstream>
#include <streambuf>

namespace py = pybind11;

namespace
{
using namespace gearstiff;
using namespace gearstiff::app;

// ---------------------------------------------------------------- MPI and PETSc start and end

// What the module started, ended at interpreter exit (Python's atexit, before the interpreter
// tears down: the last call of any gearstiff code).
std::unique_ptr<dealii::Utilities::MPI::MPI_InitFinalize> mpi_started_here;
bool petsc_started_here = false;

void start_mpi()
{
  // Python loads extension modules with RTLD_LOCAL; Open MPI then opens its components
  // (mca_*.so), which need libmpi's symbols global (what mpi4py does too).
  Dl_info info;
  if (dladdr(reinterpret_cast<void*>(&MPI_Init), &info) != 0 && info.dli_fname != nullptr)
    dlopen(info.dli_fname, RTLD_NOW | RTLD_GLOBAL | RTLD_NOLOAD);

  // MUMPS' out-of-core factors into the process's scratch folder, removed with it (app/main.cc);
  // a TMPDIR that cannot hold it is reported by the first command that needs a scratch file.
  try
  {
    if (std::getenv("MUMPS_OOC_TMPDIR") == nullptr)
      setenv("MUMPS_OOC_TMPDIR", app::scratch_directory().c_str(), 0);
  }
  catch (const InputError&)
  {
  }

  int initialised = 0;
  MPI_Initialized(&initialised);
  if (!initialised)
  {
    fem::prepare_mpi_start(); // a single process: skip Open MPI's network probing (0.5 s)
    static int argc = 1;
    static char program[] = "python3";
    static char* arguments[] = {program, nullptr};
    static char** argv = arguments;
    // MPI_Init_thread, PETSc, p4est: the same start as `gearstiff` (app/main.cc), one thread.
    mpi_started_here = std::make_unique<dealii::Utilities::MPI::MPI_InitFinalize>(argc, argv, 1);
  }
  else
  {
    // Someone else (mpi4py) started MPI and will finalise it; PETSc is ours to start and end.
    PetscBool petsc_running = PETSC_FALSE;
    PetscInitialized(&petsc_running);
    if (!petsc_running)
    {
      petsc_started_here = PetscInitializeNoArguments() == 0;
    }
  }
}

void end_mpi()
{
  if (petsc_started_here)
  {
    petsc_started_here = false;
    PetscFinalize();
  }
  mpi_started_here.reset();
}

// ---------------------------------------------------------------- exceptions

PyObject* input_error_type = nullptr;
PyObject* solver_failure_type = nullptr;

void raise_with(PyObject* type, const std::string& message, const char* attribute,
                const std::string& attribute_value)
{
  py::object error = py::reinterpret_borrow<py::object>(type)(message);
  error.attr(attribute) = attribute_value;
  PyErr_SetObject(type, error.ptr());
}

// ---------------------------------------------------------------- parameters from Python

// deal.II's JSON output (`print_parameters`; names as written in a .prm) as a nested dict.
py::object parameter_json(const dealii::ParameterHandler& prm,
                          dealii::ParameterHandler::OutputStyle style)
{
  std::ostringstream json;
  prm.print_parameters(json, style);
  return py::module_::import("json").attr("loads")(json.str());
}

// The declared parameters of a command as a nested dict: a subsection is a dict of dicts, an
// entry a dict with "value", "default_value", "documentation", "pattern", "pattern_description".
py::dict declared_tree(const dealii::ParameterHandler& prm)
{
  return py::dict(parameter_json(prm, dealii::ParameterHandler::JSON));
}

bool is_entry(const py::handle& node)
{
  if (!py::isinstance<py::dict>(node))
    return false;
  const py::dict d = py::reinterpret_borrow<py::dict>(node);
  for (const char* field : {"value", "documentation", "pattern_description"})
    if (!d.contains(field) || !py::isinstance<py::str>(d[field]))
      return false;
  return true;
}

// Levenshtein distance, letters compared without case.
std::size_t edit_distance(const std::string& a, const std::string& b)
{
  std::vector<std::size_t> previous(b.size() + 1), current(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j)
    previous[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
  {
    current[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j)
    {
      const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                        std::tolower(static_cast<unsigned char>(b[j - 1]));
      current[j] =
          std::min({previous[j] + 1, current[j - 1] + 1, previous[j - 1] + (same ? 0 : 1)});
    }
    std::swap(previous, current);
  }
  return previous[b.size()];
}

// "did you mean 'teeth'?" for the nearest declared name, or the list of names at this level.
std::string suggestion(const std::string& name, const py::dict& level)
{
  std::string nearest, all;
  std::size_t best = std::string::npos;
  for (const auto& item : level)
  {
    const std::string candidate = py::str(item.first);
    const std::size_t d = edit_distance(name, candidate);
    if (d < best)
    {
      best = d;
      nearest = candidate;
    }
    all += (all.empty() ? "'" : ", '") + candidate + "'";
  }
  if (!nearest.empty() && best <= std::max<std::size_t>(2, nearest.size() / 3))
    return "did you mean '" + nearest + "'?";
  return "the names here are " + shortened(all, 300);
}

std::string python_type(const py::handle& value)
{
  return py::str(py::type::handle_of(value).attr("__name__"));
}

// A parameter value as the text a .prm file would hold; InputError(path) for a value that is no
// scalar or list of scalars.
std::string parameter_text(const std::string& path, const py::handle& value)
{
  const py::module_ numbers = py::module_::import("numbers");
  const py::object numpy_bool = py::module_::import("numpy").attr("bool_");
  const py::object integral = numbers.attr("Integral");
  const py::object real = numbers.attr("Real");
  if (py::isinstance<py::str>(value))
    return value.cast<std::string>();
  if (py::isinstance<py::bool_>(value) || py::isinstance(value, numpy_bool))
    return value.cast<bool>() ? "true" : "false";
  if (py::isinstance(value, integral))
    return py::str(py::int_(py::reinterpret_borrow<py::object>(value)));
  if (py::isinstance(value, real))
    return py::repr(py::float_(py::reinterpret_borrow<py::object>(value)));
  if (py::isinstance<py::dict>(value))
    throw InputError(path, "expects a value, got a dict (a subsection of that name does not "
                           "exist)");
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value) ||
      py::isinstance<py::array>(value))
  {
    std::string text;
    for (const auto& element : py::iter(value))
    {
      if (py::isinstance<py::list>(element) || py::isinstance<py::tuple>(element) ||
          py::isinstance<py::dict>(element))
        throw InputError(path, "expects a value or a list of values, got a nested " +
                                   python_type(element));
      text += (text.empty() ? "" : ", ") + parameter_text(path, element);
    }
    return text;
  }
  throw InputError(path, "expects a number, text, true/false or a list of them, got " +
                             (value.is_none() ? std::string("None") : python_type(value)));
}

// The nested dict `given` checked against the declared tree and turned into the overrides of
// the command line ("section/sub/key", value).
void collect_overrides(const py::dict& given, const py::dict& declared, const std::string& prefix,
                       std::vector<std::pair<std::string, std::string>>& overrides)
{
  for (const auto& item : given)
  {
    if (!py::isinstance<py::str>(item.first))
      throw InputError(prefix.empty() ? "params" : prefix.substr(0, prefix.size() - 1),
                       "names must be strings, got " + python_type(item.first) + " " +
                           std::string(py::repr(item.first)));
    const std::string name = py::str(item.first);
    const std::string path = prefix + name;
    // "Gear pair/Pinion/teeth" as `--set` spells it: the same parameter as the nested form.
    const std::size_t slash = name.find('/');
    if (!declared.contains(name) && slash != std::string::npos && slash > 0 &&
        declared.contains(name.substr(0, slash)) &&
        !is_entry(declared[py::str(name.substr(0, slash))]))
    {
      py::dict rest;
      rest[py::str(name.substr(slash + 1))] = item.second;
      collect_overrides(rest,
                        py::reinterpret_borrow<py::dict>(declared[py::str(name.substr(0, slash))]),
                        prefix + name.substr(0, slash + 1), overrides);
      continue;
    }
    if (!declared.contains(name))
      throw InputError(path, std::string("unknown ") +
                                 (prefix.empty() ? "section" : "parameter or subsection") + "; " +
                                 suggestion(name, declared));
    const py::object node = declared[py::str(name)];
    if (is_entry(node))
      overrides.emplace_back(path, parameter_text(path, item.second));
    else if (py::isinstance<py::dict>(item.second))
      collect_overrides(py::reinterpret_borrow<py::dict>(item.second),
                        py::reinterpret_borrow<py::dict>(node), path + "/", overrides);
    else
      throw InputError(path, "is a subsection: expects a dict of its parameters, got " +
                                 python_type(item.second));
  }
}

// ---------------------------------------------------------------- results to Python

py::dict values_dict(const Report& report)
{
  py::dict values;
  for (const ReportValue& v : report.values())
  {
    py::dict entry;
    entry["value"] = v.value;
    entry["unit"] = v.unit;
    entry["description"] = v.description;
    if (!std::isnan(v.reference))
    {
      entry["published"] = v.reference;
      entry["relative_deviation"] = v.relative_deviation();
      entry["source"] = v.reference_source;
    }
    values[py::str(v.key)] = entry;
  }
  return values;
}

py::dict tables_dict(const Report& report)
{
  py::dict tables;
  for (const ReportTable& table : report.tables())
  {
    py::dict units, data, categories;
    for (std::size_t c = 0; c < table.columns.size(); ++c)
    {
      units[py::str(table.columns[c])] = table.units[c];
      if (table.categories.count(table.columns[c]))
      {
        // A categorical column by its names (a NumPy array of str), as in the CSV and JSON.
        py::list names, allowed;
        for (std::size_t r = 0; r < table.rows.size(); ++r)
          names.append(*table.category_name(r, c));
        for (const auto& [code, name] : table.categories.at(table.columns[c]))
          allowed.append(name);
        data[py::str(table.columns[c])] = py::module_::import("numpy").attr("array")(names, "U");
        categories[py::str(table.columns[c])] = allowed;
        continue;
      }
      py::array_t<double> column(static_cast<py::ssize_t>(table.rows.size()));
      auto view = column.mutable_unchecked<1>();
      for (std::size_t r = 0; r < table.rows.size(); ++r)
        view(r) = table.rows[r][c];
      data[py::str(table.columns[c])] = column;
    }
    py::dict entry;
    entry["columns"] = table.columns;
    entry["units"] = units;
    entry["data"] = data;
    entry["categories"] = categories;
    tables[py::str(table.name)] = entry;
  }
  return tables;
}

std::string command_name(const std::string& name)
{
  std::string registered = name;
  std::replace(registered.begin(), registered.end(), '_', '-');
  return registered;
}

// A null stream for the progress of a quiet run.
class NullBuffer : public std::streambuf
{
protected:
  int overflow(int c) override { return c; }
};

py::dict typed_values(const py::dict& declared);

// Notes on the input that the command line prints on stderr (a renamed parameter, sections of a
// shared pair file that other commands use) become Python warnings (UserWarning): nothing is
// printed unless verbose=True, and a script can filter them or turn them into errors.
void load_input_with_warnings(const Command& command, const Invocation& invocation,
                              dealii::ParameterHandler& prm)
{
  std::ostringstream notes;
  std::streambuf* const cerr_buffer = std::cerr.rdbuf(notes.rdbuf());
  try
  {
    load_parameters(command, invocation, prm);
  }
  catch (...)
  {
    std::cerr.rdbuf(cerr_buffer);
    throw;
  }
  std::cerr.rdbuf(cerr_buffer);
  std::istringstream lines(notes.str());
  for (std::string line; std::getline(lines, line);)
    if (!line.empty() && PyErr_WarnEx(PyExc_UserWarning, line.c_str(), 1) != 0)
      throw py::error_already_set(); // warnings turned into errors
}

// Which code produced a result, as summary.json's "gearstiff" block (app/core/build_info.h).
py::dict build_info()
{
  py::dict libraries;
  for (const auto& [name, version_text] : library_versions())
    libraries[py::str(name)] = version_text;
  py::dict info;
  info["version"] = version();
  info["revision"] = source_revision();
  info["libraries"] = libraries;
  return info;
}

py::dict run_command(const std::string& name, const py::object& params,
                     const py::object& output_directory, bool verbose)
{
  const auto start = std::chrono::steady_clock::now();
  const Command& command = find_command(command_name(name));
  Invocation invocation;
  dealii::ParameterHandler prm;
  const py::object fspath = py::module_::import("os").attr("fspath");
  if (py::isinstance<py::dict>(params))
  {
    // The names are checked against the declared tree first, so an unknown one gets a
    // suggestion; the values go through the command line's `--set` path (same messages).
    dealii::ParameterHandler declared;
    command.declare_parameters(declared);
    collect_overrides(py::reinterpret_borrow<py::dict>(params), declared_tree(declared), "",
                      invocation.overrides);
  }
  else if (py::isinstance<py::str>(params) || py::hasattr(params, "__fspath__"))
    invocation.parameter_file = py::str(fspath(params)).cast<std::string>();
  else if (!params.is_none())
    throw InputError("params", "expects a dict of sections ({\"Gear pair\": {...}}) or the path "
                               "of a .prm/.json file, got " +
                                   python_type(params));
  if (!output_directory.is_none())
  {
    invocation.output_directory = py::str(fspath(output_directory)).cast<std::string>();
    // "" wrote nothing; a name too long for the file system raised std::filesystem's text.
    check_file_name(invocation.output_directory, "output_directory");
  }
  load_input_with_warnings(command, invocation, prm);

  Report report;
  double run_seconds = 0.;
  {
    NullBuffer null_buffer;
    std::ostream null_stream(&null_buffer);
    std::unique_ptr<py::scoped_ostream_redirect> redirect;
    if (verbose) // progress to Python's sys.stdout (a notebook shows it)
      redirect = std::make_unique<py::scoped_ostream_redirect>(std::cout);
    const auto run_start = std::chrono::steady_clock::now();
    py::gil_scoped_release release; // an FE run may take minutes: let other threads run
    report = run_loaded_command(command, prm, invocation.output_directory, MPI_COMM_WORLD,
                                verbose ? std::cout : null_stream, verbose, !verbose);
    run_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - run_start).count();
  }

  py::dict result;
  result["command"] = command.name;
  result["gearstiff"] = build_info();
  py::dict text;
  for (const auto& [key, value] : report.texts())
    text[py::str(key)] = value;
  result["text"] = text;
  result["values"] = values_dict(report);
  result["tables"] = tables_dict(report);
  py::list files;
  for (const auto& file : report.output_files())
    files.append(file.first);
  result["files"] = files;
  result["parameters"] = typed_values(declared_tree(prm));
  py::dict timings;
  timings["run"] = run_seconds;
  timings["total"] =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result["timings"] = timings;
  return result;
}

// The unit stated in a parameter's documentation: the first "(mm)" or "[N·m]".
py::object unit_of(const std::string& documentation)
{
  for (std::size_t open = documentation.find_first_of("(["); open != std::string::npos;
       open = documentation.find_first_of("([", open + 1))
  {
    const char closing = documentation[open] == '(' ? ')' : ']';
    const std::size_t close = documentation.find(closing, open + 1);
    if (close == std::string::npos)
      break;
    const std::string inside = documentation.substr(open + 1, close - open - 1);
    if (!inside.empty() && inside.size() <= 16 && inside.find(' ') == std::string::npos &&
        inside.find(',') == std::string::npos && inside.find('=') == std::string::npos)
      return py::str(inside);
  }
  return py::none();
}

// A default as a Python value of the pattern's type (Integer → int, Double → float,
// Bool → bool), else the text.
py::object typed_default(const std::string& text, const std::string& pattern)
{
  try
  {
    if (pattern.rfind("[Integer", 0) == 0)
      return py::int_(std::stol(text));
    if (pattern.rfind("[Double", 0) == 0)
      return py::float_(std::stod(text));
    if (pattern.rfind("[Bool", 0) == 0)
      return py::bool_(text == "true");
  }
  catch (const std::exception&)
  {
  }
  return py::str(text);
}

// The parameters in use (the JSON listing's entries) with each value typed by its pattern, as
// the nested dict of sections a later call accepts: {'Gear pair': {'Pinion': {'teeth': 23}}}.
py::dict typed_values(const py::dict& declared)
{
  py::dict out;
  for (const auto& item : declared)
  {
    if (is_entry(item.second))
    {
      const py::dict d = py::reinterpret_borrow<py::dict>(item.second);
      out[item.first] = typed_default(py::str(d["value"]), py::str(d["pattern_description"]));
    }
    else if (py::isinstance<py::dict>(item.second))
      out[item.first] = typed_values(py::reinterpret_borrow<py::dict>(item.second));
  }
  return out;
}

py::dict describe(const py::dict& declared)
{
  py::dict out;
  for (const auto& item : declared)
  {
    if (is_entry(item.second))
    {
      const py::dict d = py::reinterpret_borrow<py::dict>(item.second);
      const std::string documentation = py::str(d["documentation"]);
      const std::string pattern = py::str(d["pattern_description"]);
      py::dict entry;
      entry["default"] = typed_default(py::str(d["default_value"]), pattern);
      entry["unit"] = unit_of(documentation);
      entry["allowed"] = d["pattern_description"];
      entry["documentation"] = documentation;
      out[item.first] = entry;
    }
    else if (py::isinstance<py::dict>(item.second))
      out[item.first] = describe(py::reinterpret_borrow<py::dict>(item.second));
  }
  return out;
}

py::dict print_parameters(const std::string& name)
{
  const Command& command = find_command(command_name(name));
  dealii::ParameterHandler prm;
  command.declare_parameters(prm);
  return describe(declared_tree(prm));
}

std::string python_name(const std::string& command) // "gear-pair" → "gear_pair"
{
  std::string name = command;
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
}
// gearstiff.InputError and gearstiff.SolverFailure, raised for the C++ exceptions of the same
// names; an IoError as OSError; deal.II's exceptions as RuntimeError.
void register_exceptions(py::module_& m)
{
  static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
  static py::exception<SolverFailure> solver_failure(m, "SolverFailure", PyExc_RuntimeError);
  input_error_type = input_error.ptr();
  solver_failure_type = solver_failure.ptr();
  input_error.attr("__doc__") =
      "Bad input; the message names the parameter (attribute `parameter`).";
  solver_failure.attr("__doc__") =
      "A numerical method failed; the message names it (attribute `method`).";
  py::register_exception_translator(
      [](std::exception_ptr thrown)
      {
        try
        {
          if (thrown)
            std::rethrow_exception(thrown);
        }
        catch (const InputError& e)
        {
          raise_with(input_error_type, one_line(e.what()), "parameter", e.parameter());
        }
        catch (const SolverFailure& e)
        {
          raise_with(solver_failure_type, one_line(e.what()), "method", e.method());
        }
        catch (const IoError& e)
        {
          // A file not written whole (a full disk, the file-size limit): Python's OSError.
          PyErr_SetString(PyExc_OSError, one_line(e.what()).c_str());
        }
        catch (const dealii::ExceptionBase& e)
        {
          PyErr_SetString(PyExc_RuntimeError, one_line(deal_ii_message(e)).c_str());
        }
      });
}

// One function per registered command, under its Python name.
void define_commands(py::module_& m)
{
  for (const auto& [name, command] : command_registry())
  {
    const std::string registered = name;
    m.def(
        python_name(name).c_str(),
        [registered](const py::object& params, const py::object& output_directory, bool verbose)
        { return run_command(registered, params, output_directory, verbose); },
        py::arg("params") = py::none(), py::arg("output_directory") = py::none(),
        py::arg("verbose") = false,
        (command.summary + ".\n\n" + command.description +
         "\n\nparams: nested dict in the .prm's sections and names (or 'Section/key' paths as "
         "--set spells them), or a .prm/.json path "
         "(None: the default case); output_directory: write the result files there as `-o` "
         "does; verbose: print progress. Returns the report as a dict (see help(gearstiff)).")
            .c_str());
  }
}

// "gear_pair, stiffness, ...": every registered command by its Python name.
std::string command_list()
{
  std::string list;
  for (const auto& [name, command] : command_registry())
    list += (list.empty() ? "" : ", ") + python_name(name);
  return list;
}
} // namespace

PYBIND11_MODULE(gearstiff, m)
{
  // OpenBLAS's kernels for this processor, as the command line takes them (fem/blas_start.h):
  // the module's results equal the command's digit for digit.
  gearstiff::fem::select_blas_kernels();
  // Every table and array the module returns is NumPy's: without it the import fails here, with
  // the package to install, not at the first call.
  try
  {
    py::module_::import("numpy");
  }
  catch (const py::error_already_set& e)
  {
    throw py::import_error("gearstiff needs NumPy (Debian: apt-get install python3-numpy; pip: "
                           "pip install numpy): " +
                           std::string(e.what()));
  }
  m.attr("__version__") = GEARSTIFF_VERSION;
  m.attr("__revision__") = source_revision();
  m.doc() = "gearstiff " GEARSTIFF_VERSION ": FE mesh stiffness, frictional contact and "
            "torsional dynamics of gear drives, in-process.\n\nOne function per command of the "
            "`gearstiff` command line (" +
            command_list() +
            "), each\n"
            "    f(params=None, output_directory=None, verbose=False) -> dict\n"
            "params: a nested dict in the .prm's sections and names "
            "({'Gear pair': {'Pinion': {'teeth': 21}}}; a key may also be a path as `--set` "
            "spells it, {'Gear pair/Pinion/teeth': 21}), or the path of a .prm/.json file; "
            "None runs the built-in default case.\n"
            "The dict returned: 'values' {key: {'value', 'unit', 'description'[, 'published', "
            "'relative_deviation', 'source']}}, 'tables' {name: {'columns', 'units', 'data': "
            "{column: numpy array; of str for a categorical column}, 'categories' {column: "
            "[the names it allows]}}}, 'text', 'files', 'gearstiff' {'version', 'revision', "
            "'libraries'} (the code that produced it), 'parameters' (the parameters used, as a "
            "dict a later call accepts; numbers as int/float, switches as bool), 'timings' {'run', "
            "'total'} [s].\n"
            "Errors: gearstiff.InputError (bad input, names the parameter) and "
            "gearstiff.SolverFailure (a numerical method failed).";

  start_mpi();
  py::module_::import("atexit").attr("register")(py::cpp_function(&end_mpi));
  register_exceptions(m);
  define_commands(m);
  m.def("print_parameters", &print_parameters, py::arg("command"),
        "The parameters of `command` ('gear_pair' or 'gear-pair') as a nested dict: for each "
        "parameter its default (typed), unit, allowed values and documentation.");
  m.def(
      "commands",
      []()
      {
        py::dict out;
        for (const auto& [name, command] : command_registry())
          out[py::str(python_name(name))] = command.summary;
        return out;
      },
      "The commands (Python names) with their one-line summaries.");
  m.def(
      "mpi_rank", []() { return dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD); },
      "This process's rank in MPI_COMM_WORLD (0 without mpirun).");
  m.def(
      "mpi_size", []() { return dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD); },
      "The number of MPI processes (1 without mpirun).");
}

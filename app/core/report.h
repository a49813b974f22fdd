// What a gearstiff command hands back to the user: named scalar values with units, short texts,
// and tables with a unit per column. The command-line driver prints it as a readable table or,
// with --json, as one JSON object; with -o DIR it is also written as summary.json and one CSV
// per table. Plain C++ so every command can fill it without further dependencies.
#pragma once

#include <cmath>
#include <deque>
#include <limits>
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace gearstiff::app
{
struct ReportValue
{
  std::string key;         // machine name, snake_case (JSON key)
  double value = 0.;       // in `unit`
  std::string unit;        // as printed, e.g. "mm", "N/m", "-"
  std::string description; // human label
  // Optional published reference value to print beside the computed one (NaN: none).
  double reference = std::numeric_limits<double>::quiet_NaN();
  std::string reference_source;
  // (value - reference)/|reference|; the value itself when the reference is 0.
  double relative_deviation() const
  {
    return reference != 0. ? (value - reference) / std::abs(reference) : value;
  }
};

struct ReportTable
{
  std::string name;                      // also the CSV file name (name.csv)
  std::vector<std::string> columns;      // snake_case column names
  std::vector<std::string> units;        // one per column
  std::vector<std::vector<double>> rows; // each row has columns.size() entries
  // Categorical columns (a sweep's direction, a run's status, a stiffness source): column name →
  // the name of each code its rows hold. Every writer (text, JSON, CSV, Python) shows the name,
  // and the JSON lists the names a column allows: a table read on its own (a spreadsheet, pandas)
  // says what its entries mean, which numeric codes explained only in the text report did not.
  std::map<std::string, std::map<int, std::string>> categories;
  void add_row(const std::vector<double>& row);
  // Makes `column` categorical: its rows hold the codes of `names` (exact small integers).
  void set_categories(const std::string& column, const std::map<int, std::string>& names);
  // The name of row `row`'s entry in column `column`, or nullptr for a numeric column.
  const std::string* category_name(std::size_t row, std::size_t column) const;
};

class Report
{
public:
  void add_value(const std::string& key, double value, const std::string& unit,
                 const std::string& description);
  // A computed value beside a published one; the deviation is printed and put in the JSON.
  void add_compared_value(const std::string& key, double value, double reference,
                          const std::string& unit, const std::string& description,
                          const std::string& reference_source);
  void add_text(const std::string& key, const std::string& text);
  ReportTable& add_table(const std::string& name, const std::vector<std::string>& columns,
                         const std::vector<std::string>& units);
  // Files the command wrote (relative to the output directory), listed at the end.
  void add_output_file(const std::string& file, const std::string& description);

  void print_text(std::ostream& out, unsigned int max_table_rows = 40) const;
  void print_json(std::ostream& out, const std::string& command) const;
  void write_table_csv(const ReportTable& table, std::ostream& out) const;

  const std::vector<ReportValue>& values() const { return value_list; }
  const std::deque<ReportTable>& tables() const { return table_list; }
  const std::vector<std::pair<std::string, std::string>>& texts() const { return text_list; }
  const std::vector<std::pair<std::string, std::string>>& output_files() const
  {
    return output_file_list;
  }
  const ReportValue* find_value(const std::string& key) const;

private:
  std::vector<ReportValue> value_list;
  std::vector<std::pair<std::string, std::string>> text_list;
  // A deque: add_table hands out references that must survive later add_table calls.
  std::deque<ReportTable> table_list;
  std::vector<std::pair<std::string, std::string>> output_file_list;
};

// The report's table `table_name` as a temporary CSV for a plot script (the report's CSV files
// appear only after the command returns), removed when this goes out of scope: the plot step of
// a command is `const TemporaryCsv csv(report, "table"); context.plot(script, {csv.path()}, ...);`.
// By name: references into the report's tables do not survive a later add_table. A write that
// fails (a full scratch disk) does not throw here, on every rank that made one: the plot that
// reads the file fails the command (temporary_write_failure), on the rank that draws.
class TemporaryCsv
{
public:
  TemporaryCsv(const Report& report, const std::string& table_name);
  ~TemporaryCsv();
  TemporaryCsv(const TemporaryCsv&) = delete;
  TemporaryCsv& operator=(const TemporaryCsv&) = delete;
  const std::string& path() const { return file; }

private:
  std::string file;
};

// Why the TemporaryCsv at `path` could not be written whole; empty when it was (or is none).
std::string temporary_write_failure(const std::string& path);

// JSON string escaping and number formatting shared by every writer in app/.
std::string json_escape(const std::string& text);
std::string json_number(double value);
} // namespace gearstiff::app

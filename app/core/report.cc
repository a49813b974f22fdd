#include "app/core/report.h"

#include "app/core/build_info.h"
#include "app/core/scratch.h"
#include "app/core/units.h"
#include "errors/io.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <map>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace gearstiff::app
{
void ReportTable::add_row(const std::vector<double>& row)
{
  if (row.size() != columns.size())
    throw std::logic_error("table '" + name + "': row has " + std::to_string(row.size()) +
                           " entries, expected " + std::to_string(columns.size()));
  rows.push_back(row);
  for (std::size_t c = 0; c < columns.size(); ++c)
    category_name(rows.size() - 1, c); // an unknown code is a programming error: thrown here
}

void ReportTable::set_categories(const std::string& column, const std::map<int, std::string>& names)
{
  if (std::find(columns.begin(), columns.end(), column) == columns.end())
    throw std::logic_error("table '" + name + "': no column '" + column + "' to name");
  categories[column] = names;
  const std::size_t c = std::find(columns.begin(), columns.end(), column) - columns.begin();
  for (std::size_t r = 0; r < rows.size(); ++r)
    category_name(r, c);
}

const std::string* ReportTable::category_name(std::size_t row, std::size_t column) const
{
  const auto names = categories.find(columns[column]);
  if (names == categories.end())
    return nullptr;
  const double code = rows[row][column];
  const auto found = names->second.find(static_cast<int>(std::lround(code)));
  if (!std::isfinite(code) || found == names->second.end() || found->first != code)
    throw std::logic_error("table '" + name + "': code " + std::to_string(code) + " of column '" +
                           columns[column] + "' has no name");
  return &found->second;
}

void Report::add_value(const std::string& key, double value, const std::string& unit,
                       const std::string& description)
{
  ReportValue entry; // no published reference: `reference` stays NaN
  entry.key = key;
  entry.value = value;
  entry.unit = unit;
  entry.description = description;
  value_list.push_back(entry);
}

void Report::add_compared_value(const std::string& key, double value, double reference,
                                const std::string& unit, const std::string& description,
                                const std::string& reference_source)
{
  add_value(key, value, unit, description);
  value_list.back().reference = reference;
  value_list.back().reference_source = reference_source;
}

void Report::add_text(const std::string& key, const std::string& text)
{
  text_list.emplace_back(key, text);
}

ReportTable& Report::add_table(const std::string& name, const std::vector<std::string>& columns,
                               const std::vector<std::string>& units)
{
  if (columns.size() != units.size())
    throw std::logic_error("table '" + name + "': columns and units differ in number");
  std::vector<std::string> ascii_units;
  for (const std::string& unit : units)
    ascii_units.push_back(table_unit(unit));
  table_list.push_back(ReportTable{name, columns, ascii_units, {}, {}});
  return table_list.back();
}

void Report::add_output_file(const std::string& file, const std::string& description)
{
  output_file_list.emplace_back(file, description);
}

const ReportValue* Report::find_value(const std::string& key) const
{
  for (const auto& v : value_list)
    if (v.key == key)
      return &v;
  return nullptr;
}

namespace
{
// Characters shown, not bytes: labels carry UTF-8 symbols (α, ε, ·) and std::setw pads by
// bytes, which would shift the value column.
std::size_t display_width(const std::string& text)
{
  std::size_t width = 0;
  for (const unsigned char c : text)
    width += (c & 0xC0) != 0x80;
  return width;
}

std::string pad(const std::string& text, std::size_t width)
{
  const std::size_t shown = display_width(text);
  return shown >= width ? text : text + std::string(width - shown, ' ');
}

std::string format_number(double x)
{
  if (!std::isfinite(x))
    return std::isnan(x) ? "nan" : (x > 0 ? "inf" : "-inf");
  std::ostringstream s;
  const double a = std::abs(x);
  if (a != 0. && (a >= 1e7 || a < 1e-3))
    s << std::scientific << std::setprecision(5) << x;
  else
    s << std::setprecision(7) << x;
  return s.str();
}

// A CSV field as RFC 4180 reads it: quoted when it holds a separator, a quote or a line break.
std::string csv_field(const std::string& text)
{
  if (text.find_first_of(",\"\n") == std::string::npos)
    return text;
  std::string quoted = "\"";
  for (const char c : text)
    quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

// One table as text: a column per entry, right-aligned, its unit under its name, a category's
// name where the column is categorical; at most `max_rows` rows.
void print_table(std::ostream& out, const ReportTable& table, unsigned int max_rows)
{
  out << '\n' << table.name << " (" << table.rows.size() << " rows)\n";
  std::vector<std::size_t> widths;
  for (std::size_t c = 0; c < table.columns.size(); ++c)
  {
    std::size_t longest_name = 0;
    const auto names = table.categories.find(table.columns[c]);
    if (names != table.categories.end())
      for (const auto& [code, category] : names->second)
        longest_name = std::max(longest_name, display_width(category) + 1);
    widths.push_back(
        std::max<std::size_t>(std::max<std::size_t>(13, longest_name),
                              std::max(table.columns[c].size(), table.units[c].size() + 2) + 1));
  }
  for (std::size_t c = 0; c < table.columns.size(); ++c)
    out << std::right << std::setw(widths[c]) << table.columns[c];
  out << '\n';
  for (std::size_t c = 0; c < table.columns.size(); ++c)
    out << std::right << std::setw(widths[c]) << ("[" + table.units[c] + "]");
  out << '\n';
  std::size_t printed = 0;
  for (std::size_t r = 0; r < table.rows.size(); ++r)
  {
    if (printed++ == max_rows)
    {
      out << "  ... " << table.rows.size() - max_rows
          << " more rows (use -o DIR for the CSV, or --json)\n";
      break;
    }
    for (std::size_t c = 0; c < table.columns.size(); ++c)
    {
      const std::string* category = table.category_name(r, c);
      const std::string cell = category ? *category : format_number(table.rows[r][c]);
      out << std::string(widths[c] - std::min(widths[c], display_width(cell)), ' ') << cell;
    }
    out << '\n';
  }
}
} // namespace

void Report::print_text(std::ostream& out, unsigned int max_table_rows) const
{
  std::size_t label_width = 0;
  for (const auto& v : value_list)
    label_width = std::max(label_width, display_width(v.description));
  std::size_t key_width = 0;
  for (const auto& t : text_list)
    key_width = std::max(key_width, display_width(t.first));

  for (const auto& t : text_list)
    out << pad(t.first, key_width + 2) << t.second << '\n';
  if (!text_list.empty())
    out << '\n';

  bool any_reference = false;
  for (const auto& v : value_list)
    any_reference = any_reference || !std::isnan(v.reference);

  if (!value_list.empty())
  {
    out << pad("quantity", label_width + 2) << std::right << std::setw(14) << "value"
        << "  " << pad("unit", 12);
    if (any_reference)
      out << std::right << std::setw(14) << "published" << std::setw(11) << "deviation"
          << "  source";
    out << '\n';
    for (const auto& v : value_list)
    {
      out << pad(v.description, label_width + 2) << std::right << std::setw(14)
          << format_number(v.value) << "  " << pad(v.unit, 12);
      if (!std::isnan(v.reference))
      {
        const double deviation = v.relative_deviation();
        std::ostringstream d;
        d << std::showpos << std::fixed << std::setprecision(2) << 100. * deviation << " %";
        out << std::right << std::setw(14) << format_number(v.reference) << std::setw(11) << d.str()
            << "  " << v.reference_source;
      }
      out << '\n';
    }
  }

  for (const auto& table : table_list)
    print_table(out, table, max_table_rows);

  if (!output_file_list.empty())
  {
    out << "\nfiles written:\n";
    for (const auto& f : output_file_list)
      out << "  " << std::left << std::setw(32) << f.first << f.second << '\n';
  }
}

std::string json_escape(const std::string& text)
{
  std::ostringstream s;
  s << '"';
  for (const char c : text)
  {
    switch (c)
    {
    case '"':
      s << "\\\"";
      break;
    case '\\':
      s << "\\\\";
      break;
    case '\n':
      s << "\\n";
      break;
    case '\t':
      s << "\\t";
      break;
    default:
      if (static_cast<unsigned char>(c) < 0x20)
        s << "\\u" << std::hex << std::setw(4) << std::setfill('0') << int(c) << std::dec;
      else
        s << c;
    }
  }
  s << '"';
  return s.str();
}

std::string json_number(double value)
{
  if (!std::isfinite(value))
    return "null"; // JSON has no NaN/inf; a null is never mistaken for a result
  std::ostringstream s;
  s << std::setprecision(12) << value;
  return s.str();
}

void Report::print_json(std::ostream& out, const std::string& command) const
{
  // Which code produced these results (app/core/build_info.h): the regression comparison and
  // the earlier-results check read the keys beside it, never this block.
  out << "{\n  \"command\": " << json_escape(command)
      << ",\n  \"gearstiff\": {\"version\": " << json_escape(version())
      << ", \"revision\": " << json_escape(source_revision()) << ", \"libraries\": {";
  const auto libraries = library_versions();
  for (std::size_t i = 0; i < libraries.size(); ++i)
    out << (i ? ", " : "") << json_escape(libraries[i].first) << ": "
        << json_escape(libraries[i].second);
  out << "}},\n  \"text\": {";
  for (std::size_t i = 0; i < text_list.size(); ++i)
    out << (i ? ",\n    " : "\n    ") << json_escape(text_list[i].first) << ": "
        << json_escape(text_list[i].second);
  out << (text_list.empty() ? "" : "\n  ") << "},\n  \"values\": {";
  for (std::size_t i = 0; i < value_list.size(); ++i)
  {
    const auto& v = value_list[i];
    out << (i ? ",\n    " : "\n    ") << json_escape(v.key)
        << ": {\"value\": " << json_number(v.value) << ", \"unit\": " << json_escape(v.unit)
        << ", \"description\": " << json_escape(v.description);
    if (!std::isnan(v.reference))
      out << ", \"published\": " << json_number(v.reference)
          << ", \"relative_deviation\": " << json_number(v.relative_deviation())
          << ", \"source\": " << json_escape(v.reference_source);
    out << "}";
  }
  out << (value_list.empty() ? "" : "\n  ") << "},\n  \"tables\": {";
  for (std::size_t t = 0; t < table_list.size(); ++t)
  {
    const auto& table = table_list[t];
    out << (t ? ",\n    " : "\n    ") << json_escape(table.name) << ": {\"columns\": [";
    for (std::size_t c = 0; c < table.columns.size(); ++c)
      out << (c ? ", " : "") << json_escape(table.columns[c]);
    out << "], \"units\": [";
    for (std::size_t c = 0; c < table.units.size(); ++c)
      out << (c ? ", " : "") << json_escape(table.units[c]);
    out << "]";
    if (!table.categories.empty())
    {
      out << ", \"categories\": {";
      bool first_column = true;
      for (const auto& column : table.columns) // in column order, not the map's
      {
        const auto names = table.categories.find(column);
        if (names == table.categories.end())
          continue;
        out << (first_column ? "" : ", ") << json_escape(column) << ": [";
        first_column = false;
        bool first_name = true;
        for (const auto& [code, category] : names->second)
        {
          out << (first_name ? "" : ", ") << json_escape(category);
          first_name = false;
        }
        out << "]";
      }
      out << "}";
    }
    out << ", \"rows\": [";
    for (std::size_t r = 0; r < table.rows.size(); ++r)
    {
      out << (r ? ", [" : "[");
      for (std::size_t c = 0; c < table.rows[r].size(); ++c)
      {
        const std::string* category = table.category_name(r, c);
        out << (c ? ", " : "")
            << (category ? json_escape(*category) : json_number(table.rows[r][c]));
      }
      out << "]";
    }
    out << "]}";
  }
  out << (table_list.empty() ? "" : "\n  ") << "},\n  \"files\": [";
  for (std::size_t i = 0; i < output_file_list.size(); ++i)
    out << (i ? ", " : "") << json_escape(output_file_list[i].first);
  out << "]\n}\n";
}

void Report::write_table_csv(const ReportTable& table, std::ostream& out) const
{
  for (std::size_t c = 0; c < table.columns.size(); ++c)
    out << (c ? "," : "") << table.columns[c] << " [" << table.units[c] << "]";
  out << '\n' << std::setprecision(12);
  for (std::size_t r = 0; r < table.rows.size(); ++r)
  {
    for (std::size_t c = 0; c < table.columns.size(); ++c)
    {
      out << (c ? "," : "");
      if (const std::string* category = table.category_name(r, c))
        out << csv_field(*category);
      else
        out << table.rows[r][c];
    }
    out << '\n';
  }
}

namespace
{
// TemporaryCsv files not written whole, by path: the reason (errors/io.h).
std::mutex failed_temporaries_mutex;
std::map<std::string, std::string> failed_temporaries;
} // namespace

TemporaryCsv::TemporaryCsv(const Report& report, const std::string& table_name)
    : file((std::filesystem::path(scratch_directory()) / (table_name + ".csv")).string())
{
  try
  {
    write_file(file,
               [&](std::ostream& out)
               {
                 for (const auto& table : report.tables())
                   if (table.name == table_name)
                     report.write_table_csv(table, out);
               });
  }
  catch (const IoError& e)
  {
    const std::lock_guard<std::mutex> lock(failed_temporaries_mutex);
    failed_temporaries[file] = e.reason();
  }
}

TemporaryCsv::~TemporaryCsv()
{
  {
    const std::lock_guard<std::mutex> lock(failed_temporaries_mutex);
    failed_temporaries.erase(file);
  }
  std::error_code ignored; // a leftover temporary file is no reason to fail a command
  std::filesystem::remove(file, ignored);
}

std::string temporary_write_failure(const std::string& path)
{
  const std::lock_guard<std::mutex> lock(failed_temporaries_mutex);
  const auto found = failed_temporaries.find(path);
  return found == failed_temporaries.end() ? "" : found->second;
}
} // namespace gearstiff::app

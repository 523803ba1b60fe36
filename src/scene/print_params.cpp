// The parameter reference, generated from the registry in two layouts: aligned
// text for the terminal (`rkpm params`) and markdown for the documentation.
#include "rkpm/scene/param_registry.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <ostream>
#include <sstream>

namespace rkpm::scene {
namespace {

using Row = std::array<std::string, 6>;
const Row kHeader = {"key", "type", "unit", "default", "range", "description"};

Row row_of(const ParamSpec& spec) {
  std::string type = type_name(spec.type);
  if (spec.length != 0) type = fmt::format("{} ({})", type, spec.length);
  return {spec.name, type, spec.unit, spec.default_text(), spec.range_text(), spec.help_text};
}

std::string joined(const std::vector<std::string>& words, const char* quote) {
  std::string out;
  for (const auto& w : words) out += fmt::format("{}{}{}{}", out.empty() ? "" : " ", quote, w, quote);
  return out;
}

// Greedy word wrap to `width` columns; continuation lines start at `indent`.
std::string wrapped(const std::string& text, std::size_t indent, std::size_t width) {
  std::istringstream words(text);
  std::string word, out;
  std::size_t column = indent;
  while (words >> word) {
    if (column > indent && column + 1 + word.size() > width) {
      out += "\n" + std::string(indent, ' ');
      column = indent;
    }
    if (column > indent) {
      out += ' ';
      ++column;
    }
    out += word;
    column += word.size();
  }
  return out;
}

void print_text_table(std::ostream& out, const ParamTable& table) {
  out << table.heading() << "\n  " << wrapped(table.help, 2, 100) << "\n";
  if (!table.surfaces.empty()) out << "  surfaces: " << joined(table.surfaces, "") << "\n";
  std::vector<Row> rows = {kHeader};
  for (const auto& spec : table.specs) rows.push_back(row_of(spec));
  std::array<std::size_t, 5> width{};
  for (const auto& r : rows) {
    for (std::size_t c = 0; c < width.size(); ++c) width[c] = std::max(width[c], r[c].size());
  }
  std::size_t help_column = 2;
  for (auto w : width) help_column += w + 2;
  for (const auto& r : rows) {
    out << "  ";
    for (std::size_t c = 0; c < width.size(); ++c) out << r[c] << std::string(width[c] + 2 - r[c].size(), ' ');
    out << wrapped(r[5], help_column, std::max<std::size_t>(help_column + 40, 120)) << "\n";
  }
  out << "\n";
}

std::string md_cell(const std::string& text, bool code) {
  std::string escaped;
  for (char c : text) {
    if (c == '|') escaped += '\\';
    escaped += c;
  }
  return code && text != "required" ? "`" + escaped + "`" : escaped;
}

void print_markdown_table(std::ostream& out, const ParamTable& table) {
  out << "### `" << table.heading() << "`\n\n" << table.help << "\n\n";
  if (!table.surfaces.empty()) out << "Surfaces: " << joined(table.surfaces, "`") << "\n\n";
  out << "| key | type | unit | default | range | description |\n|---|---|---|---|---|---|\n";
  for (const auto& spec : table.specs) {
    const Row r = row_of(spec);
    const bool literal_default = spec.required || spec.default_value.has_value();
    out << "| " << md_cell(r[0], true) << " | " << r[1] << " | " << md_cell(r[2], false) << " | "
        << md_cell(r[3], literal_default) << " | " << md_cell(r[4], false) << " | " << md_cell(r[5], false)
        << " |\n";
  }
  out << "\n";
}

}  // namespace

void print_params(std::ostream& out, ParamFormat format) {
  for (const auto& table : ParamRegistry::instance().tables()) {
    if (format == ParamFormat::markdown) {
      print_markdown_table(out, table);
    } else {
      print_text_table(out, table);
    }
  }
}

}  // namespace rkpm::scene

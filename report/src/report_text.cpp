// write_text_summary: the report as an aligned plain-text table (no colours: it may be piped).

#include "meshprep/report/report_writers.h"

#include "report_summary.h"

#include <algorithm>
#include <iomanip>

namespace meshprep {
namespace {

using detail::Check;
using detail::SummaryRow;
using detail::SummarySection;
using detail::SummaryTable;

constexpr std::size_t kIndent = 2;

// Rows that are checks start with "OK" or "!" so that problems stand out.
std::string marked_label(const SummaryRow& row) {
  switch (row.check) {
    case Check::ok: return "OK " + row.label;
    case Check::problem: return "!  " + row.label;
    case Check::none: break;
  }
  return row.label;
}

std::size_t label_width(const std::vector<const SummarySection*>& sections) {
  std::size_t width = 0;
  for (const SummarySection* section : sections)
    for (const SummaryRow& row : section->rows) width = std::max(width, marked_label(row).size());
  return width;
}

void write_rows(std::ostream& out, const SummarySection& section, std::size_t width) {
  for (const SummaryRow& row : section.rows)
    out << std::string(kIndent, ' ') << std::left << std::setw(int(width + 2)) << marked_label(row) << row.value
        << '\n';
}

void write_section(std::ostream& out, const SummarySection& section, std::size_t width) {
  out << section.title << '\n';
  write_rows(out, section, width);
}

// Width of each column: its longest cell (header included).
std::vector<std::size_t> column_widths(const SummaryTable& table) {
  std::vector<std::size_t> widths;
  for (const std::string& name : table.header) widths.push_back(name.size());
  for (const auto& row : table.rows)
    for (std::size_t c = 0; c < row.size(); ++c) widths[c] = std::max(widths[c], row[c].size());
  return widths;
}

// The first column is left-aligned (labels), the others right-aligned (numbers). The header row is
// not indented so that it reads as the table's title.
void write_table_row(std::ostream& out, const std::vector<std::string>& cells, const std::vector<std::size_t>& widths,
                     std::size_t indent) {
  out << std::string(indent, ' ') << std::left << std::setw(int(widths[0] + kIndent - indent)) << cells[0]
      << std::right;
  for (std::size_t c = 1; c < cells.size(); ++c) out << "  " << std::setw(int(widths[c])) << cells[c];
  out << std::left << '\n';
}

void write_table(std::ostream& out, const SummaryTable& table) {
  const std::vector<std::size_t> widths = column_widths(table);
  write_table_row(out, table.header, widths, 0);
  for (const auto& row : table.rows) write_table_row(out, row, widths, kIndent);
}

}  // namespace

void write_text_summary(std::ostream& out, const QualityReport& report) {
  const detail::Summary summary = detail::make_summary(report);
  std::vector<const SummarySection*> sections{&summary.counts};
  for (const SummarySection& section : summary.sections) sections.push_back(&section);
  sections.push_back(&summary.shape_fractions);
  if (summary.reference) sections.push_back(&*summary.reference);
  const std::size_t width = label_width(sections);
  const std::ios_base::fmtflags caller_flags = out.flags();

  out << "Mesh quality: " << summary.file << '\n';
  write_rows(out, summary.counts, width);  // the counts read as the file's details, without a title
  for (const SummarySection& section : summary.sections) write_section(out, section, width);
  write_table(out, summary.face_shape);
  write_section(out, summary.shape_fractions, width);
  if (!summary.worst_faces.rows.empty()) write_table(out, summary.worst_faces);
  if (summary.reference) write_section(out, *summary.reference, width);
  out.flags(caller_flags);
}

}  // namespace meshprep

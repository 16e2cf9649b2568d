#pragma once
/// \file report_summary.h
/// The figures of a QualityReport as formatted strings, grouped as the text summary and the HTML
/// page show them (private to the module: both renderers use it so that they show the same figures).

#include "meshprep/quality/report.h"

#include <optional>
#include <string>
#include <vector>

namespace meshprep::detail {

/// Whether a row states a problem (the text summary marks it "!") or its absence ("OK").
enum class Check { none, ok, problem };

struct SummaryRow {
  std::string label;
  std::string value;
  Check check = Check::none;
};

struct SummarySection {
  std::string title;
  std::vector<SummaryRow> rows;
};

struct SummaryTable {
  std::vector<std::string> header;             ///< one name per column, the first one names the table
  std::vector<std::vector<std::string>> rows;  ///< each as long as the header
};

struct Summary {
  std::string file;                      ///< the report's path, or a placeholder for an in-memory mesh
  SummarySection counts;
  std::vector<SummarySection> sections;  ///< topology, problems, geometry
  SummaryTable face_shape;               ///< distribution of each per-face metric
  SummarySection shape_fractions;        ///< faces beyond the FEM-grade thresholds, in percent
  SummaryTable worst_faces;
  std::optional<SummarySection> reference;
};

Summary make_summary(const QualityReport& report);

/// 4 significant digits; "-" for NaN (an empty distribution).
std::string format_figure(double v);

/// A fraction in [0, 1] as a percentage with 2 decimals ("3.25 %").
std::string format_percent(double fraction);

}  // namespace meshprep::detail

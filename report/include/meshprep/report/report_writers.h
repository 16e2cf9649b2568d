#pragma once
/// \file report_writers.h
/// Ways to present a QualityReport: JSON (the machine interface; keys are stable), a text summary
/// table, a per-face CSV, a VTK file for ParaView with every per-face metric as cell data and the
/// per-vertex surface variation as point data, and one self-contained HTML page with inline SVG
/// histograms and pictures of the surface. File writers are atomic.

#include "meshprep/core/mesh.h"
#include "meshprep/quality/report.h"

#include <nlohmann/json.hpp>

#include <ostream>
#include <string>

namespace meshprep {

/// The report as JSON (ordered keys). Non-finite numbers and empty optionals become null.
nlohmann::ordered_json to_json(const QualityReport& report);

/// A readable summary table (what `meshprep quality` prints).
void write_text_summary(std::ostream& out, const QualityReport& report);

/// One row per face: index, the three vertex indices, every TriangleShape field.
void write_csv(const std::string& path, const TriangleSoup& soup, const QualityReport& report);

/// Legacy VTK polydata (binary) with every per-face metric as CELL_DATA scalars and the surface
/// variation sigma of every vertex (surface_variation.h, computed here from `soup`) as POINT_DATA
/// scalars "surface_variation".
void write_vtk(const std::string& path, const TriangleSoup& soup, const QualityReport& report);

/// The same data as write_vtk in VTK's XML unstructured-grid format (.vtu: triangles, cell data
/// per metric plus "degenerate", point data "surface_variation"), which ParaView and meshio read.
void write_vtu(const std::string& path, const TriangleSoup& soup, const QualityReport& report);

/// One self-contained page: checks in green/red, pictures of `soup` coloured by radius ratio
/// (surface_picture.h), the summary, an SVG histogram per metric.
void write_html(const std::string& path, const TriangleSoup& soup, const QualityReport& report);

}  // namespace meshprep

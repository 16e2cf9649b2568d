#include "stages.h"

#include "arrays.h"
#include "calls.h"
#include "keywords.h"

#include "meshprep/commands/simplify_command.h"
#include "meshprep/commands/surface_commands.h"
#include "meshprep/commands/tet_commands.h"
#include "meshprep/commands/tet_mesh_report.h"
#include "meshprep/core/errors.h"
#include "meshprep/core/io.h"
#include "meshprep/fem/export.h"
#include "meshprep/fem/import.h"
#include "meshprep/fem/readiness.h"
#include "meshprep/pipeline/pipeline.h"
#include "meshprep/pipeline/pipeline_outputs.h"
#include "meshprep/report/report_writers.h"

#include <pybind11/stl.h>

namespace meshprep::python {
namespace {

// A path argument: str or os.PathLike.
std::string path_of(const py::handle& value, const char* what) {
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::hasattr(value, "__fspath__")) return value.attr("__fspath__")().cast<std::string>();
  throw InvalidInput(std::string(what) + ": expected a path (str or os.PathLike)");
}

py::object surface_object(TriangleSoup soup) { return py::cast(Surface{std::make_shared<TriangleSoup>(std::move(soup))}); }
py::object tets_object(TetMesh mesh) { return py::cast(Tets{std::make_shared<TetMesh>(std::move(mesh))}); }

const TriangleSoup& surface_arg(const py::handle& value, const char* what) {
  if (!py::isinstance<Surface>(value))
    throw InvalidInput(std::string(what) + ": expected a meshprep.Surface, not " +
                       std::string(py::str(value.get_type().attr("__name__"))));
  return *value.cast<const Surface&>().soup;
}

const TriangleSoup* optional_surface(const py::handle& value, const char* what) {
  return value.is_none() ? nullptr : &surface_arg(value, what);
}

// What a call returns to meshprep/__init__.py, which makes it a Result.
py::dict result(py::object mesh, const nlohmann::ordered_json& report, const CommandMessages& messages,
                std::optional<bool> fem_ready) {
  py::dict out;
  out["mesh"] = std::move(mesh);
  out["report"] = report.dump();
  out["messages"] = messages;
  out["fem_ready"] = fem_ready ? py::object(py::bool_(*fem_ready)) : py::none();
  return out;
}

CancelToken* token_of(const py::handle& cancel) {
  if (cancel.is_none()) return nullptr;
  if (!py::isinstance<CancelToken>(cancel)) throw InvalidInput("cancel: expected a meshprep.CancelToken");
  return &cancel.cast<CancelToken&>();
}

// The keywords every call takes beside the configuration keys, as the command line's flags:
// threads for its parallel parts (0 = all cores, --threads) and time_limit, the whole call's
// deadline in seconds (0 = none, --time-limit); taken out of `kw`.
CallOptions take_call_options(py::dict& kw) {
  CallOptions options;
  if (kw.contains("threads")) {
    const py::object value = kw.attr("pop")("threads");
    if (!py::isinstance<py::int_>(value) || py::isinstance<py::bool_>(value) || value.cast<long long>() < 0)
      throw InvalidInput("threads: expected an integer >= 0 (0 = all cores), not " + std::string(py::repr(value)));
    options.threads = value.cast<std::size_t>();
  }
  if (kw.contains("time_limit")) {
    const py::object value = kw.attr("pop")("time_limit");
    const bool number = (py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value)) && !py::isinstance<py::bool_>(value);
    const double seconds = number ? value.cast<double>() : -1;
    if (!(seconds >= 0 && std::isfinite(seconds)))
      throw InvalidInput("time_limit: expected a number of seconds >= 0 (0 = none), not " + std::string(py::repr(value)));
    options.time_limit_seconds = seconds;
  }
  return options;
}

// The names messages give a call's input and output.
CommandNames names_of(const std::string& function) { return {"meshprep." + function + "() input", "the result"}; }

// The surface argument as load_mesh reads a file, named for the messages; its halfedge mesh is
// built by build_mesh, in the call (without the GIL).
LoadedMesh input_of(const py::object& surface, const std::string& function) {
  LoadedMesh input;
  input.soup = surface_arg(surface, "surface");
  input.read.path = names_of(function).input;
  return input;
}

void build_mesh(LoadedMesh& input) { input.mesh = mesh_from_soup(input.soup, &input.build); }

// ---- the keywords of each call, and the defaults they start from (the command line's) ----

const Keywords kSimplify{"simplify", "simplify", {"quality"}, {"enabled"}};
const Keywords kSmooth{"smooth", "smooth", {"quality"}, {"enabled"}};
const Keywords kEnhance{"enhance", "enhance", {"quality", "size"}, {"enabled"}};
const Keywords kRepair{"repair", "repair", {}, {"enabled"}};
const Keywords kReconstruct{"reconstruct", "reconstruct", {}, {}};
const Keywords kQuality{"quality", "quality", {}, {}};
const Keywords kTetrahedralize{
    "tetrahedralize", "tetrahedralize", {"improve", "verdict", "patches", "size"}, {"enabled", "format", "msh_version", "binary", "ascii"}};
const Keywords kImprove{"improve", "improve", {"verdict"}, {"enabled"}};
const Keywords kPipeline{"pipeline", "", {"repair", "reconstruct", "patches", "simplify", "smooth", "size", "enhance", "knife_edges", "quality",
                                          "tetrahedralize", "improve", "verdict"}, {}};

// The configuration whose sections hold the standalone commands' defaults (the pipeline's differ:
// pipeline_config.h).
PipelineConfig command_defaults() {
  PipelineConfig config;
  config.reconstruct.params = ReconstructParams{};
  config.smooth.params = SmoothParams{};
  config.enhance.params = EnhanceParams{};
  config.quality.params = QualityParams{};
  config.tetrahedralize.keep_surface = TetParams{}.keep_surface;  // `meshprep tetrahedralize`'s, not "auto"
  return config;
}

PipelineConfig configured(const Keywords& spec, const py::dict& keywords) {
  PipelineConfig config = command_defaults();
  apply_keywords(spec, keywords, config);
  return config;
}

// ---- the calls ----

py::dict call_simplify(const py::object& surface, const py::object& progress, const py::object& cancel, py::dict kw) {
  const CallOptions options = take_call_options(kw);
  const PipelineConfig config = configured(kSimplify, kw);
  SimplifyCommand command;
  command.params = config.simplify.params;
  if (config.simplify.ratio.has_value() == (command.params.target_faces > 0))
    throw InvalidInput("meshprep.simplify(): give exactly one of ratio and target_faces");
  command.params.keep_ratio = config.simplify.ratio.value_or(1.0);
  command.quality = config.quality.params;
  LoadedMesh input = input_of(surface, "simplify");
  CallControl control(progress, token_of(cancel), options);
  const CommandHooks hooks = control.hooks("simplify");
  SimplifyOutcome outcome = control.run([&] {
    build_mesh(input);
    return simplify_command(std::move(input), command, names_of("simplify"), hooks);
  });
  return result(surface_object(std::move(outcome.surface)), outcome.report, outcome.messages, std::nullopt);
}

py::dict call_smooth(const py::object& surface, const py::object& progress, const py::object& cancel, py::dict kw) {
  const CallOptions options = take_call_options(kw);
  const PipelineConfig config = configured(kSmooth, kw);
  const SmoothCommand command{config.smooth.params, config.quality.params};
  LoadedMesh input = input_of(surface, "smooth");
  CallControl control(progress, token_of(cancel), options);
  const CommandHooks hooks = control.hooks("smooth");
  SmoothOutcome outcome = control.run([&] {
    build_mesh(input);
    return smooth_command(std::move(input), command, names_of("smooth"), hooks);
  });
  return result(surface_object(std::move(outcome.surface)), outcome.report, outcome.messages, std::nullopt);
}

py::dict call_enhance(const py::object& surface, const py::object& reference, const py::object& progress,
                      const py::object& cancel, py::dict kw) {
  const CallOptions options = take_call_options(kw);
  const PipelineConfig config = configured(kEnhance, kw);
  EnhanceCommand command{config.enhance.params, config.quality.params};
  command.params.size = config.size;
  LoadedMesh input = input_of(surface, "enhance");
  const TriangleSoup* against = optional_surface(reference, "reference");
  CallControl control(progress, token_of(cancel), options);
  const CommandHooks hooks = control.hooks("enhance");
  EnhanceOutcome outcome = control.run([&] {
    build_mesh(input);
    return enhance_command(std::move(input), against, "reference", command, names_of("enhance"), hooks);
  });
  return result(surface_object(std::move(outcome.surface)), outcome.report, outcome.messages, std::nullopt);
}

py::dict call_repair(const py::object& surface, const py::object& cancel, py::dict kw) {
  const CallOptions options = take_call_options(kw);
  const PipelineConfig config = configured(kRepair, kw);
  TriangleSoup input = surface_arg(surface, "surface");
  CallControl control(py::none(), token_of(cancel), options);
  const CommandHooks hooks = control.hooks("repair");
  RepairOutcome outcome =
      control.run([&] { return repair_command(std::move(input), config.repair.params, names_of("repair"), hooks); });
  return result(surface_object(std::move(outcome.surface)), outcome.report, outcome.messages, std::nullopt);
}

py::dict call_reconstruct(const py::object& points, const py::object& progress, const py::object& cancel, py::dict kw) {
  const CallOptions options = take_call_options(kw);
  const PipelineConfig config = configured(kReconstruct, kw);
  const ReconstructCommand command{config.reconstruct.params, config.reconstruct.adaptive};
  const std::vector<Vec3> samples = points_from_array(points, "points");
  CallControl control(progress, token_of(cancel), options);
  const CommandHooks hooks = control.hooks("reconstruct");
  ReconstructOutcome outcome =
      control.run([&] { return reconstruct_command(samples, command, names_of("reconstruct"), hooks); });
  return result(surface_object(std::move(outcome.surface)), outcome.report, outcome.messages, std::nullopt);
}

py::dict call_check(const py::object& surface) {
  const TriangleSoup& soup = surface_arg(surface, "surface");
  CallControl control(py::none(), nullptr, CallOptions{});
  const Readiness readiness = control.run([&] { return check_fem_readiness(soup); });
  return result(py::none(), to_json(readiness), {}, readiness.ready());
}

py::dict call_quality(const py::object& mesh, const py::object& reference, py::dict kw) {
  const CallOptions options = take_call_options(kw);
  const PipelineConfig config = configured(kQuality, kw);
  CallControl control(py::none(), nullptr, options);
  if (py::isinstance<Tets>(mesh)) {
    if (!reference.is_none()) throw InvalidInput("meshprep.quality(): reference is for surfaces, not tet meshes");
    const TetMesh& tets = *mesh.cast<const Tets&>().mesh;
    const nlohmann::ordered_json report = control.run([&] { return tet_mesh_report(tets, TetReadReport{}); });
    return result(py::none(), report, {}, std::nullopt);
  }
  const TriangleSoup& soup = surface_arg(mesh, "mesh");
  const TriangleSoup* against = optional_surface(reference, "reference");
  const nlohmann::ordered_json report =
      control.run([&] { return nlohmann::ordered_json(to_json(analyze_quality(soup, config.quality.params, against))); });
  return result(py::none(), report, {}, std::nullopt);
}

// The tet calls' finishing (improvement, second order, verdict) from their configuration.
TetFinishing finishing_of(const PipelineConfig& config) {
  TetFinishing finishing;
  finishing.improve = config.improve.enabled;
  finishing.improve_params = config.improve.params;
  finishing.element_order = config.tetrahedralize.element_order;
  finishing.thresholds = config.verdict;
  return finishing;
}

py::dict tet_result(TetOutcome outcome) {
  // As the command line: a surface that is not FEM-ready is bad input (2), TetGen failing is failed work (3).
  if (!outcome.failure.empty()) {
    if (outcome.readiness && !outcome.readiness->ready()) throw InvalidInput(outcome.failure);
    throw SolverError(outcome.failure);
  }
  const bool ready = outcome.fem_ready();
  return result(tets_object(std::move(outcome.tets)), outcome.report, outcome.messages, ready);
}

py::dict call_tetrahedralize(const py::object& surface, const py::object& progress, const py::object& cancel,
                             py::dict kw) {
  const CallOptions options = take_call_options(kw);
  PipelineConfig config = command_defaults();
  // The surface is extruded only when asked (the pipeline's default depth is for its terrains).
  const bool extrude = kw.contains("extrude_base") || kw.contains("extrude_base_relative");
  apply_keywords(kTetrahedralize, kw, config);
  TetrahedralizeCommand command;
  command.params = config.tetrahedralize.params;
  if (config.tetrahedralize.keep_surface) command.params.keep_surface = *config.tetrahedralize.keep_surface;
  command.finishing = finishing_of(config);
  command.patches = config.patches.params;
  command.size = config.size;
  if (extrude) {
    command.extrude_depth = config.tetrahedralize.extrude_base;
    command.extrude_relative = kw.contains("extrude_base_relative") ? config.tetrahedralize.extrude_base_relative : 0;
  }
  const TriangleSoup& soup = surface_arg(surface, "surface");
  CallControl control(progress, token_of(cancel), options);
  const CommandHooks hooks = control.hooks("tetrahedralize");
  return tet_result(control.run([&] { return tetrahedralize_command(soup, command, names_of("tetrahedralize"), hooks); }));
}

py::dict call_improve(const py::object& tets, const py::object& reference, const py::object& progress,
                      const py::object& cancel, py::dict kw) {
  const CallOptions options = take_call_options(kw);
  PipelineConfig config = command_defaults();
  if (kw.contains("order")) {  // the tetrahedralize section's key, as the command line's --order
    apply_config({{"tetrahedralize", {{"order", json_value(kw["order"], "order")}}}}, "meshprep.improve()", config);
    kw = kw.attr("copy")();
    PyDict_DelItemString(kw.ptr(), "order");
  }
  apply_keywords(kImprove, kw, config);
  if (!py::isinstance<Tets>(tets)) throw InvalidInput("tets: expected a meshprep.TetMesh");
  TetMesh mesh = *tets.cast<const Tets&>().mesh;
  const TriangleSoup* against = optional_surface(reference, "reference");
  const TetFinishing finishing = finishing_of(config);
  CallControl control(progress, token_of(cancel), options);
  const CommandHooks hooks = control.hooks("improve");
  return tet_result(
      control.run([&] { return improve_command(std::move(mesh), against, finishing, names_of("improve"), hooks); }));
}

py::dict call_pipeline(const py::object& input, const py::object& outdir, const py::object& config_arg,
                       const py::object& progress, const py::object& cancel, py::dict kw) {
  const CallOptions options = take_call_options(kw);
  PipelineConfig config;
  if (py::isinstance<py::dict>(config_arg)) {
    apply_config(json_value(config_arg, "config"), "meshprep.pipeline() config", config);
  } else if (!config_arg.is_none()) {
    read_config_file(path_of(config_arg, "config"), config);
  }
  apply_keywords(kPipeline, kw, config);
  // A file, or a Surface or points in memory (named "<surface>" / "<points>" in the report).
  PipelineInput given;
  std::string path;
  if (py::isinstance<Surface>(input)) {
    given.name = path = "<surface>";
    given.surface = *input.cast<const Surface&>().soup;
  } else if (py::isinstance<py::array>(input)) {
    given.name = path = "<points>";
    given.points = points_from_array(input, "input");
  } else {
    path = path_of(input, "input");
  }
  const std::string folder = outdir.is_none() ? std::string() : path_of(outdir, "outdir");
  if (!folder.empty()) check_output_dir(folder);
  CallControl control(progress, token_of(cancel), options);
  PipelineObserver observer;
  observer.stage_started = [&control](const std::string& stage) { control.set_stage(stage); };
  observer.progress = [&control](double fraction) {
    if (control.poll(fraction)) throw Cancelled("cancelled");
  };
  observer.cancelled = [&control] { return control.poll(-1); };
  observer.deadline = control.deadline();
  PipelineResult run = control.run([&] {
    PipelineResult result = given.name.empty() ? run_pipeline(path, config, observer) : run_pipeline(given, config, observer);
    if (!folder.empty()) {
      nlohmann::ordered_json record;
      record["input"] = path;
      record["versions"] = build_versions();
      write_pipeline_outputs(result, config, folder, record, observer.cancelled);
    }
    return result;
  });
  const nlohmann::ordered_json summary = pipeline_summary(run, config);
  py::dict out = result(surface_object(std::move(run.surface)), summary, {}, run.fem.ready);
  out["tets"] = run.tets ? tets_object(std::move(*run.tets)) : py::none();
  out["tetrahedralized"] = config.tetrahedralize.enabled;
  return out;
}

// The docstring of a call: what it does, then its keywords with the command line's defaults.
std::string doc(const char* what, const Keywords& spec) {
  return std::string(what) + "\n\nKeywords (the configuration file's keys, docs/pipeline.md):\n" +
         keyword_doc(spec, command_defaults()) +
         "    threads (integer >= 0, default 0): threads for this call's parallel parts; 0 = all cores\n"
         "    time_limit (seconds >= 0, default 0): the whole call's limit; the enhancement and the tet improvement "
         "end there with their best result, any other step raises TimeoutError; 0 = none\n";
}

}  // namespace

void register_meshes(py::module_& m) {
  py::class_<Surface>(m, "Surface", "A triangle surface: points (n, 3) float64, faces (m, 3) uint32, patches per face.")
      .def(py::init(&surface_from_arrays), py::arg("points"), py::arg("faces"), py::arg("patches") = py::none(),
           py::arg("patch_names") = py::none(),
           "Copies the arrays (checked: float64 (n, 3) finite points, integer (m, 3) faces indexing them, C-contiguous)")
      .def_property_readonly("points", [](py::object self) { return points_view(self.cast<Surface&>().soup->points, self); },
                             "(n, 3) float64, read-only, no copy")
      .def_property_readonly("faces", [](py::object self) { return index_view<3>(self.cast<Surface&>().soup->triangles, self); },
                             "(m, 3) uint32, read-only, no copy")
      .def_property_readonly("patches",
                             [](py::object self) -> py::object {
                               const TriangleSoup& soup = *self.cast<Surface&>().soup;
                               if (soup.patches.empty()) return py::none();
                               return tags_view(soup.patches, self);
                             },
                             "(m,) int32 tag per face (read-only), or None")
      .def_property_readonly("patch_names", [](const Surface& s) { return names_dict(s.soup->patch_names); })
      .def("write",
           [](const Surface& s, const py::object& path, bool binary) {
             WriteOptions options;
             options.binary = binary;
             const std::string file = path_of(path, "path");
             py::gil_scoped_release release;
             write_soup(*s.soup, file, options);
           },
           py::arg("path"), py::arg("binary") = false, "Writes .off .obj .ply .stl (binary: PLY and STL), atomically")
      .def("__repr__", [](const Surface& s) {
        return "<meshprep.Surface: " + std::to_string(s.soup->points.size()) + " points, " +
               std::to_string(s.soup->triangles.size()) + " faces>";
      });

  py::class_<Tets>(m, "TetMesh", "Tetrahedra: points (n, 3) float64, tets (k, 4) uint32, boundary faces with patches.")
      .def(py::init(&tets_from_arrays), py::arg("points"), py::arg("tets"), py::arg("boundary_faces") = py::none(),
           py::arg("patches") = py::none(), py::arg("patch_names") = py::none(),
           "Copies the arrays (checked as Surface's); the boundary is the tets' own, tag 1, when not given")
      .def_property_readonly("points", [](py::object self) { return points_view(self.cast<Tets&>().mesh->points, self); })
      .def_property_readonly("tets", [](py::object self) { return index_view<4>(self.cast<Tets&>().mesh->tets, self); })
      .def_property_readonly("boundary_faces",
                             [](py::object self) { return index_view<3>(self.cast<Tets&>().mesh->boundary_faces, self); })
      .def_property_readonly("patches", [](py::object self) { return tags_view(self.cast<Tets&>().mesh->boundary_tags, self); },
                             "(f,) int32 tag per boundary face, read-only")
      .def_property_readonly("patch_names", [](const Tets& t) { return names_dict(t.mesh->boundary_names); })
      .def_property_readonly("regions", [](py::object self) { return tags_view(self.cast<Tets&>().mesh->tet_regions, self); })
      .def_property_readonly("quadratic", [](const Tets& t) { return t.mesh->quadratic(); })
      .def("write",
           [](const Tets& t, const py::object& path, const std::string& msh_version, bool binary, bool ascii) {
             TetExportOptions options;
             options.msh_version = msh_version == "2.2" ? MshVersion::V22 : MshVersion::V41;
             if (msh_version != "2.2" && msh_version != "4.1")
               throw InvalidInput("msh_version: expected \"4.1\" or \"2.2\", not \"" + msh_version + "\"");
             options.binary = binary;
             options.ascii = ascii;
             const std::string file = path_of(path, "path");
             check_tet_export_options(file, options);
             py::gil_scoped_release release;
             write_tet_mesh(*t.mesh, file, options);
           },
           py::arg("path"), py::arg("msh_version") = "4.1", py::arg("binary") = false, py::arg("ascii") = false,
           "Writes .msh .vtu .vtk .mesh .node .inp .xdmf (format from the extension), atomically")
      .def("__repr__", [](const Tets& t) {
        return "<meshprep.TetMesh: " + std::to_string(t.mesh->points.size()) + " points, " +
               std::to_string(t.mesh->tets.size()) + (t.mesh->quadratic() ? " 10-node" : "") + " tets, " +
               std::to_string(t.mesh->boundary_faces.size()) + " boundary faces>";
      });

  py::class_<CancelToken>(m, "CancelToken", "Pass as cancel=; .cancel() from any thread stops the call (meshprep.Cancelled)")
      .def(py::init<>())
      .def("cancel", [](CancelToken& t) { t.cancelled = true; })
      .def_property_readonly("cancelled", [](const CancelToken& t) { return t.cancelled.load(); });

  m.def("read",
        [](const py::object& path) -> py::object {
          const std::string file = path_of(path, "path");
          if (is_tet_mesh_path(file)) {
            TetMesh mesh;
            {
              py::gil_scoped_release release;
              mesh = read_tet_mesh(file);
            }
            return tets_object(std::move(mesh));
          }
          if (is_surface_mesh_path(file)) {
            TriangleSoup soup;
            {
              py::gil_scoped_release release;
              soup = read_soup(file);
            }
            return surface_object(std::move(soup));
          }
          const PointSet points = read_points(file);  // .xyz: an (n, 3) array
          py::array_t<double> array({static_cast<py::ssize_t>(points.points.size()), py::ssize_t{3}});
          std::copy(points.points.front().data(), points.points.front().data() + 3 * points.points.size(),
                    array.mutable_data());
          return std::move(array);
        },
        py::arg("path"), "A Surface (.off .obj .ply .stl), a TetMesh (.msh .vtu .vtk .mesh .node .ele .xdmf) or points (.xyz)");
}

void register_stages(py::module_& m) {
  m.def("_simplify", &call_simplify);
  m.def("_smooth", &call_smooth);
  m.def("_enhance", &call_enhance);
  m.def("_repair", &call_repair);
  m.def("_reconstruct", &call_reconstruct);
  m.def("_check", &call_check);
  m.def("_quality", &call_quality);
  m.def("_tetrahedralize", &call_tetrahedralize);
  m.def("_improve", &call_improve);
  m.def("_pipeline", &call_pipeline);
  py::dict docs;
  docs["simplify"] = doc("Reduces a surface by edge collapse (meshprep simplify).", kSimplify);
  docs["smooth"] = doc("Smooths a surface (meshprep smooth).", kSmooth);
  docs["enhance"] = doc("The statistical enhancement against the input or a reference (meshprep enhance).", kEnhance);
  docs["repair"] = doc("Mends a dirty surface (meshprep repair).", kRepair);
  docs["reconstruct"] = doc("A surface from an (n, 3) point array (meshprep reconstruct).", kReconstruct);
  docs["quality"] = doc("The quality report of a Surface (against a reference) or a TetMesh (meshprep quality).", kQuality);
  docs["tetrahedralize"] = doc("Tets of a closed surface, improved and judged (meshprep tetrahedralize). An open height "
                               "field is closed into a block only when extrude_base or extrude_base_relative is given.",
                               kTetrahedralize);
  docs["improve"] = doc("Improves a TetMesh and judges it (meshprep improve); order=2 makes it second-order.", kImprove);
  docs["pipeline"] = doc("The whole pipeline (meshprep pipeline) on a file, a Surface or an (n, 3) point array; outdir "
                         "gets its outputs.", kPipeline);
  m.attr("_docs") = docs;
}

}  // namespace meshprep::python

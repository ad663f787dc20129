// reconfig sculpt MESH --tool SPEC --coating L --at X,Y,Z (--translate | --scale | --rotate)... -o OUT.obj
// — deforms a mesh by a tool swept along strokes, foldover-free and checked (docs/file-formats.md,
// "reconfig sculpt").

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "command.h"
#include "reconfig/common/input_error.h"
#include "reconfig/geometry/load_mesh.h"
#include "reconfig/geometry/mesh_check.h"
#include "reconfig/geometry/save_mesh.h"
#include "reconfig/sculpt/sculpt_stroke.h"

namespace reconfig::cli {
namespace {

struct SculptOptions {
  std::string mesh;
  std::string tool;
  double coating = 0;
  std::string at = "0,0,0";
  std::vector<std::string> translate, scale, rotate;
  std::string mirror;
  int substeps = 0;
  double remesh = 0;
  std::string output;
  bool json = false;
};

/// One stroke as given on the command line, in order.
struct StrokeArgument {
  std::string flag;   ///< "--translate", "--scale" or "--rotate"
  std::string value;
};

std::vector<double> numbers(const std::string& flag, const std::string& text, std::size_t count) {
  std::vector<double> values;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    std::size_t used = 0;
    double value = 0;
    try {
      value = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != item.size() || !std::isfinite(value))
      throw InputError("", flag, fmt::format("\"{}\" is not a number", item));
    values.push_back(value);
  }
  if (values.size() != count) throw InputError("", flag, fmt::format("expected {} comma-separated numbers, got \"{}\"", count, text));
  return values;
}

Eigen::Vector3d vector3(const std::string& flag, const std::string& text) {
  const std::vector<double> v = numbers(flag, text, 3);
  return {v[0], v[1], v[2]};
}

void require_positive(const std::string& flag, const Eigen::Vector3d& v) {
  if (!(v.minCoeff() > 0)) throw InputError("", flag, "sizes must be > 0");
}

sculpt::Tool make_tool(const SculptOptions& options) {
  if (!(options.coating > 0)) throw InputError("", "--coating", "the coating thickness must be > 0");
  const Eigen::Vector3d at = vector3("--at", options.at);
  const std::size_t colon = options.tool.find(':');
  const std::string kind = options.tool.substr(0, colon), spec = colon == std::string::npos ? "" : options.tool.substr(colon + 1);
  if (kind == "sphere") {
    const double radius = numbers("--tool", spec, 1)[0];
    require_positive("--tool", Eigen::Vector3d::Constant(radius));
    return sculpt::Tool::sphere(radius, at, options.coating);
  }
  if (kind == "box") {
    const Eigen::Vector3d size = vector3("--tool", spec);
    require_positive("--tool", size);
    return sculpt::Tool::box(size, at, options.coating);
  }
  if (kind == "capsule") {
    const std::vector<double> v = numbers("--tool", spec, 2);
    require_positive("--tool", Eigen::Vector3d(v[0], v[1] + 1, 1));
    if (v[1] < 0) throw InputError("", "--tool", "the capsule's length must be ≥ 0");
    return sculpt::Tool::capsule(v[0], v[1], at, options.coating);
  }
  if (kind == "ellipsoid") {
    const Eigen::Vector3d radii = vector3("--tool", spec);
    require_positive("--tool", radii);
    return sculpt::Tool::ellipsoid(radii, at, options.coating);
  }
  if (kind == "mesh" && !spec.empty()) {
    geometry::Mesh mesh = geometry::load_mesh(spec);
    const geometry::MeshReport report = geometry::check_mesh(mesh);
    if (!report.is_valid_solid())
      throw InputError(spec, "", "a mesh tool must be a closed, manifold, outward-oriented solid (see `reconfig info`)");
    mesh.V.rowwise() += at.transpose();
    return sculpt::Tool::baked(mesh, options.coating);
  }
  throw InputError("", "--tool", fmt::format("\"{}\": expected sphere:R, box:X,Y,Z, capsule:R,LENGTH, ellipsoid:A,B,C or mesh:FILE", options.tool));
}

sculpt::ToolMotion make_motion(const StrokeArgument& stroke, const sculpt::Tool& tool) {
  const Eigen::Vector3d center = tool.field_box().center();
  if (stroke.flag == "--translate") return sculpt::ToolMotion::translation(vector3(stroke.flag, stroke.value));
  if (stroke.flag == "--scale") {
    const double factor = numbers(stroke.flag, stroke.value, 1)[0];
    if (!(factor > 0)) throw InputError("", stroke.flag, "the scaling factor must be > 0");
    return sculpt::ToolMotion::scaling(factor, center);
  }
  const std::size_t comma = stroke.value.rfind(',');
  if (comma == std::string::npos) throw InputError("", stroke.flag, "expected AXIS,DEGREES (AXIS: x, y, z or AX,AY,AZ)");
  const std::string axis_text = stroke.value.substr(0, comma);
  const double degrees = numbers(stroke.flag, stroke.value.substr(comma + 1), 1)[0];
  Eigen::Vector3d axis;
  if (axis_text == "x" || axis_text == "y" || axis_text == "z") axis = Eigen::Vector3d::Unit(axis_text[0] - 'x');
  else axis = vector3(stroke.flag, axis_text);
  if (!(axis.norm() > 0)) throw InputError("", stroke.flag, "the rotation axis must not be zero");
  return sculpt::ToolMotion::rotation(axis, degrees * M_PI / 180, center);
}

sculpt::MirrorPlane mirror_plane(const std::string& text) {
  if (text.empty()) return {};
  if (text == "x" || text == "y" || text == "z") return {text[0] - 'x', 0.0};
  throw InputError("", "--mirror", fmt::format("\"{}\": expected x, y or z (the plane through the origin)", text));
}

/// The strokes in the order they were given on the command line.
std::vector<StrokeArgument> strokes_in_order(const CLI::App& command, const SculptOptions& options) {
  std::vector<StrokeArgument> strokes;
  std::size_t used[3] = {0, 0, 0};
  const std::vector<std::string>* values[3] = {&options.translate, &options.scale, &options.rotate};
  const std::string flags[3] = {"--translate", "--scale", "--rotate"};
  for (const CLI::Option* option : command.parse_order())
    for (int k = 0; k < 3; ++k)
      if (option->get_name() == flags[k] && used[k] < values[k]->size())
        strokes.push_back({flags[k], (*values[k])[used[k]++]});
  return strokes;
}

int run_sculpt(const SculptOptions& options, const std::vector<StrokeArgument>& strokes) {
  if (strokes.empty()) throw InputError("", "", "give at least one stroke: --translate, --scale or --rotate");
  const auto start = std::chrono::steady_clock::now();
  geometry::Mesh mesh = geometry::load_mesh(options.mesh);
  const int triangles_before = mesh.face_count();
  sculpt::Tool tool = make_tool(options);
  sculpt::StrokeOptions stroke_options;
  stroke_options.mirror = mirror_plane(options.mirror);
  stroke_options.substeps = options.substeps;
  stroke_options.remesh = {options.remesh, options.remesh / 4};
  nlohmann::ordered_json report = nlohmann::ordered_json::array();
  Eigen::MatrixX3d no_normals(0, 3);
  for (std::size_t i = 0; i < strokes.size(); ++i) {
    const auto stroke_start = std::chrono::steady_clock::now();
    const sculpt::ToolMotion motion = make_motion(strokes[i], tool);
    const sculpt::StrokeResult result = sculpt::sculpt_mesh({{tool, motion}}, stroke_options, mesh, no_normals);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - stroke_start).count();
    report.push_back({{"stroke", strokes[i].flag.substr(2) + " " + strokes[i].value},
                      {"applied", result.applied},
                      {"substeps", result.substeps},
                      {"foldover_bound", result.foldover_bound},
                      {"min_jacobian_determinant", result.min_jacobian_determinant},
                      {"vertices_moved", result.vertices_moved},
                      {"splits", result.splits},
                      {"collapses", result.collapses},
                      {"seconds", seconds}});
    if (!result.applied) {
      report.back()["refusal"] = result.refusal;
      if (options.json) fmt::print("{}\n", nlohmann::ordered_json{{"mesh", options.mesh}, {"strokes", report}}.dump(2));
      std::fprintf(stderr, "reconfig: error: stroke %zu (%s %s) refused, nothing written: %s\n", i + 1,
                   strokes[i].flag.c_str(), strokes[i].value.c_str(), result.refusal.c_str());
      return kExitBadInput;
    }
    if (!options.json)
      fmt::print("stroke {} ({} {}): {} sub-steps (bound {:.3g}), {} vertices moved, least det J {:.4g}\n", i + 1,
                 strokes[i].flag, strokes[i].value, result.substeps, result.foldover_bound, result.vertices_moved,
                 result.min_jacobian_determinant);
    tool = result.tools.front();
  }
  geometry::save_obj(options.output, mesh);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (options.json) {
    const nlohmann::ordered_json root = {{"mesh", options.mesh},           {"output", options.output},
                                         {"vertices", mesh.vertex_count()}, {"triangles_before", triangles_before},
                                         {"triangles_after", mesh.face_count()}, {"seconds", seconds},
                                         {"strokes", report}};
    fmt::print("{}\n", root.dump(2));
  } else {
    fmt::print("wrote {} ({} vertices, {} triangles; {:.3f} s)\n", options.output, mesh.vertex_count(), mesh.face_count(), seconds);
  }
  return kExitOk;
}

}  // namespace

void add_sculpt_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<SculptOptions>();
  CLI::App* command = app.add_subcommand("sculpt", "Deform a mesh with a tool swept along strokes (foldover-free, checked)");
  command->add_option("mesh", options->mesh, "Mesh to sculpt (OBJ, STL, PLY, OFF, glTF)")->required();
  command->add_option("--tool", options->tool, "sphere:R | box:X,Y,Z | capsule:R,LENGTH | ellipsoid:A,B,C | mesh:FILE")->required();
  command->add_option("--coating", options->coating, "Coating thickness λ: how far beyond the tool space deforms")->required();
  command->add_option("--at", options->at, "X,Y,Z: the tool's center (a mesh tool: added to its coordinates)");
  command->add_option("--translate", options->translate, "DX,DY,DZ: a stroke moving the tool (repeatable)")->allow_extra_args(false);
  command->add_option("--scale", options->scale, "F: a stroke scaling the tool about its center (repeatable)")->allow_extra_args(false);
  command->add_option("--rotate", options->rotate, "AXIS,DEGREES: a stroke turning the tool about its center; AXIS x, y, z or AX,AY,AZ (repeatable)")
      ->allow_extra_args(false);
  command->add_option("--mirror", options->mirror, "x, y or z: the tool also acts mirrored in that coordinate plane");
  command->add_option("--substeps", options->substeps, "Force this many sub-steps per stroke (default: from the foldover bound)")
      ->check(CLI::PositiveNumber);
  command->add_option("--remesh", options->remesh,
                      "L: between sub-steps, split edges longer than L and collapse those shorter than L/4 in the tool's reach")
      ->check(CLI::PositiveNumber);
  command->add_option("-o,--output", options->output, "Output mesh (.obj)")->required();
  command->add_flag("--json", options->json, "Print the report as JSON");
  command->callback([options, command, &exit_code] {
    if (std::filesystem::path(options->output).extension() != ".obj") throw InputError(options->output, "", "output must end in .obj");
    exit_code = run_sculpt(*options, strokes_in_order(*command, *options));
  });
}

}  // namespace reconfig::cli

// Hostile input, end to end: bad scenes, bad meshes, bad paths and absurd requests each get
// a clear message (file:line where there is one) and the documented exit code, and never
// crash, hang or touch the output an earlier run left. Scene messages in detail:
// tests/scene/invalid_input_test.cpp; fuzzing: fuzz/.

#include <unistd.h>

#include <algorithm>

#include <gtest/gtest.h>

#include "clip/limits.h"
#include "common/error.h"
#include "scene/load.h"
#include "support/run.h"
#include "world/world.h"

namespace systole::test {
namespace {

namespace fs = std::filesystem;

const std::string kEarlier = "an earlier clip that must survive\n";
/// Tiny and short: the point is the input, not the pixels.
const std::string kTiny = "output: {width: 64, height: 64, duration: 0.1 s}\n";

std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

std::string mesh_scene(const std::string& file, const std::string& units = "cm") {
  return "organs:\n  - name: organ\n    mesh: {file: \"" + file + "\", units: " + units + "}\n" + kTiny;
}

/// A folder with a scene and an earlier output, the way a user's project looks.
struct Project {
  fs::path dir, scene, video;
  explicit Project(const std::string& name, const std::string& scene_text = "")
      : dir(scratch("invalid_" + name)), scene(dir / "scene.yaml"), video(dir / "clip.mp4") {
    if (!scene_text.empty()) write_file(scene, scene_text);
    write_file(video, kEarlier);
  }
  RunResult render(const std::string& extra = "") const {
    return run(systole() + " render " + quoted(scene) + " -o " + quoted(video) + " " + extra);
  }
  /// Files in the folder other than the scene, its meshes and the earlier clip: none may be left.
  std::vector<std::string> leftovers() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) {
      const std::string name = e.path().filename().string();
      if (name.find(".partial-") != std::string::npos) names.push_back(name);
    }
    return names;
  }
};

/// The run failed with `code` and `message`, and left the earlier clip as it was.
void expect_rejected(const Project& p, const RunResult& r, int code, const std::string& message) {
  EXPECT_EQ(r.exit_code, code) << r.output;
  EXPECT_NE(r.output.find(message), std::string::npos) << "expected '" << message << "' in:\n" << r.output;
  EXPECT_EQ(r.output.find("internal error"), std::string::npos) << r.output;
  EXPECT_EQ(read_file(p.video), kEarlier) << "the earlier output is byte-identical";
  EXPECT_TRUE(p.leftovers().empty()) << "no temporary file is left: " << p.leftovers().front();
}

void expect_rejected(const std::string& name, const std::string& scene_text, int code, const std::string& message) {
  SCOPED_TRACE(name);
  const Project p(name, scene_text);
  expect_rejected(p, p.render(), code, p.scene.string() + message);
}

// --- Scene files ---------------------------------------------------------------------------

TEST(InvalidInput, EmptyTruncatedAndGarbageScenes) {
  expect_rejected("empty", " ", 65, ":1:1: missing required key 'organs'");
  const std::string heart = read_file(source("scenes/heart.yaml"));
  // Cut inside a flow map ({...): the parser reaches the end of the text looking for '}'.
  const std::string truncated = heart.substr(0, heart.find(": {") + 8);
  const auto end_line = std::to_string(std::count(truncated.begin(), truncated.end(), '\n') + 1);
  expect_rejected("truncated", truncated, 65, ":" + end_line + ":1: invalid YAML: end of map flow not found");
  std::string garbage;
  for (int i = 0; i < 512; ++i) garbage += static_cast<char>((i * 7919 + 13) % 256);
  expect_rejected("garbage", garbage, 65, ":1:64: invalid YAML: unknown escape character");
  expect_rejected("scalar", "just words\n", 65, ":1:1: expected a map");
}

TEST(InvalidInput, NanInfNegativeAndZeroInTheFileNameTheLineAndKey) {
  const std::string organ = "organs:\n  - name: heart\n    mesh: {procedural: heart, detail: 1}\n";
  expect_rejected("nan_mass", organ + "    body: {mass: .nan}\n", 65, ":4:18: organs[0].body.mass: expected a finite number");
  expect_rejected("inf_stiffness", organ + "    body: {stiffness: -.inf N/m}\n", 65,
                  ":4:23: organs[0].body.stiffness: expected a finite number");
  expect_rejected("negative_mass", organ + "    body: {mass: -1 kg}\n", 65, ":4:18: organs[0].body.mass: -1 kg is outside");
  expect_rejected("huge_fov", organ + "camera: {fov: 1e308 deg}\n", 65, ":4:15: camera.fov:");
  expect_rejected("zero_fps", organ + "output: {fps: 0}\n", 65, ":4:15: output.fps: 0 is outside (0, 240]");
  expect_rejected("negative_fps", organ + "output: {fps: -30}\n", 65, ":4:15: output.fps: -30 is outside (0, 240]");
  expect_rejected("zero_duration", organ + "output: {duration: 0 s}\n", 65, ":4:20: output.duration: 0 s is outside");
  expect_rejected("negative_duration", organ + "output: {duration: -5 s}\n", 65, ":4:20: output.duration: -5 s is outside");
  expect_rejected("wrong_type", organ + "output: {width: [1280]}\n", 65, ":4:17: output.width: expected a whole number");
  expect_rejected("odd_size", organ + "output: {width: 321, height: 240}\n", 65, ":4:17: output.width: 321 is odd");
  expect_rejected("tiny_size", organ + "output: {width: 2, height: 2}\n", 65, ":4:17: output.width: 2 is outside 16..7680");
}

TEST(InvalidInput, MissingAndUnreadableScenes) {
  const Project p("missing_scene");
  expect_rejected(p, p.render(), 66, p.scene.string());
  const Project d("scene_is_a_folder");
  fs::create_directory(d.scene);
  expect_rejected(d, d.render(), 66, d.scene.string());
}

// --- Mesh files -------------------------------------------------------------------------------

/// Writes `mesh_text` as `file_name` beside the scene and renders it.
RunResult render_mesh(const Project& p, const std::string& file_name, const std::string& mesh_text,
                      const std::string& units = "cm") {
  write_file(p.dir / file_name, mesh_text);
  write_file(p.scene, mesh_scene(file_name, units));
  return p.render();
}

TEST(InvalidInput, EmptyTruncatedAndGarbageMeshes) {
  struct Case {
    std::string name, file, text, message;
  };
  std::string garbage;
  for (int i = 0; i < 4096; ++i) garbage += static_cast<char>((i * 2654435761u) >> 13);
  const std::vector<Case> cases = {
      {"empty_obj", "organ.obj", "", "cannot read as a mesh"},
      {"no_faces", "organ.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n", "organ.obj: "},
      {"truncated_obj", "organ.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2", "organ.obj: "},
      {"garbage_stl", "organ.stl", garbage, "organ.stl"},
      {"garbage_glb", "organ.glb", "glTF" + garbage, "organ.glb: "},
      {"ten_million_vertices_claimed", "organ.ply",
       "ply\nformat ascii 1.0\nelement vertex 10000000\nproperty float x\nproperty float y\nproperty float z\n"
       "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
       "organ.ply: cannot read as a mesh (the PLY header promises at least 60000002 bytes of elements"},
      {"index_out_of_range", "organ.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n", "organ.obj"},
      {"all_degenerate", "organ.obj", "v 0 0 0\nv 1 0 0\nf 1 2 2\nf 1 1 1\n", "organ.obj"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const Project p("mesh_" + c.name);
    expect_rejected(p, render_mesh(p, c.file, c.text), 65, c.message);
  }
}

/// Two closed tetrahedra as OBJ text, scaled and optionally inside out.
std::string tetrahedra(double scale, bool inside_out, bool two_pieces) {
  std::string text;
  auto add = [&](double dx, int base) {
    const double v[4][3] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    for (const auto& p : v) {
      char line[160];
      std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", (p[0] + dx) * scale, p[1] * scale, p[2] * scale);
      text += line;
    }
    const int f[4][3] = {{1, 2, 3}, {1, 4, 2}, {1, 3, 4}, {2, 4, 3}};
    for (const auto& t : f) {
      text += "f " + std::to_string(base + t[0]) + " " + std::to_string(base + (inside_out ? t[2] : t[1])) + " " +
              std::to_string(base + (inside_out ? t[1] : t[2])) + "\n";
    }
  };
  add(0, 0);
  if (two_pieces) add(4, 4);
  return text;
}

TEST(InvalidInput, OddButUsableMeshesRender) {
  // Reported by `validate`, simulated as they are: an open sheet has no volume constraint,
  // a non-manifold fan and an inside-out surface are kept (the latter flipped outwards).
  struct Case {
    std::string name, text;
  };
  const std::vector<Case> cases = {
      {"one_triangle", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"},
      {"nonmanifold_fan", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\nf 1 2 5\n"},
      {"inside_out", tetrahedra(1, true, false)},
      {"two_pieces", tetrahedra(1, false, true)},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const Project p("usable_" + c.name);
    const RunResult r = render_mesh(p, "organ.obj", c.text);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(read_file(p.video), kEarlier) << "a successful run replaces the clip";
    EXPECT_TRUE(p.leftovers().empty());
  }
}

TEST(InvalidInput, MeshesNoOrganCouldBeAreRefusedWithTheUnitsToWrite) {
  // 1e30 m and 1e-30 m across: beyond any organ and below any spring's numerical reach.
  for (const double scale : {1e30, 1e-30}) {
    SCOPED_TRACE(scale);
    const Project p(scale > 1 ? "coordinates_huge" : "coordinates_tiny");
    expect_rejected(p, render_mesh(p, "organ.obj", tetrahedra(scale, false, false), "m"), 65,
                    p.scene.string() + ":2:5: organ 'organ': the mesh is " + (scale > 1 ? "3.46e+30 m" : "3.46e-30 m") +
                        " across, but an organ is 5 mm to 2 m across, so its units are wrong; no unit (m, cm, mm) "
                        "makes it organ-sized");
  }
  // A mesh in metres (17 cm across) declared in millimetres: the message says what to write.
  const Project p("units_mm_on_metres");
  expect_rejected(p, render_mesh(p, "organ.obj", tetrahedra(0.05, false, false), "mm"), 65,
                  "the mesh is 0.000173 m across, but an organ is 5 mm to 2 m across, so its units are wrong; write "
                  "`units: m` (then it is 17.3 cm across)");
}

TEST(InvalidInput, WrongUnitsGivenByADefineNameTheDefineNotTheScenesLine) {
  const Project p("units_from_define");
  write_file(p.dir / "organ.obj", tetrahedra(0.05, false, false));
  write_file(p.scene, mesh_scene("organ.obj", "m"));
  expect_rejected(p, p.render("-D organs.0.mesh.units=mm"), 65,
                  "-D organs.0.mesh.units=mm: organ 'organ': the mesh is 0.000173 m across, but an organ is 5 mm to 2 m "
                  "across, so its units are wrong; write `units: m`");
}

TEST(InvalidInput, MissingAndUnreadableMeshPathsNameTheLine) {
  const Project p("mesh_missing", mesh_scene("nowhere/organ.obj"));
  expect_rejected(p, p.render(), 66, p.scene.string() + ":3:18: organs[0].mesh.file: mesh file " + (p.dir / "nowhere/organ.obj").string() + " is not found");
  const Project d("mesh_is_a_folder", mesh_scene("folder.obj"));
  fs::create_directory(d.dir / "folder.obj");
  expect_rejected(d, d.render(), 66, "folder.obj");
  const Project f("mesh_is_a_device", mesh_scene("/dev/zero"));
  expect_rejected(f, f.render(), 66, ":3:18: organs[0].mesh.file: mesh file /dev/zero is not a regular file");
}

// --- Paths ----------------------------------------------------------------------------------------

/// `command` as an unprivileged user when the tests run as root (as CI does), since root
/// may write into read-only folders and read unreadable files; "" when that is impossible.
std::string unprivileged(const std::string& command) {
  if (::geteuid() != 0) return command;
  const std::string drop = "setpriv --reuid=65534 --regid=65534 --clear-groups ";
  if (run(drop + "test -x " + SYSTOLE_BINARY).exit_code != 0) return "";
  return drop + "env " + command;
}

TEST(InvalidInput, OutputIntoAMissingOrReadOnlyFolderIsCannotCreate) {
  const Project p("output_missing_folder", "organs: [{name: heart, mesh: {procedural: heart, detail: 1}}]\n" + kTiny);
  const RunResult r = run(systole() + " render " + quoted(p.scene) + " -o " + quoted(p.dir / "missing" / "clip.mp4"));
  expect_rejected(p, r, 73, (p.dir / "missing").string() + "' does not exist");

  const Project ro("output_read_only", "organs: [{name: heart, mesh: {procedural: heart, detail: 1}}]\n" + kTiny);
  fs::permissions(ro.dir, fs::perms::owner_write | fs::perms::group_write | fs::perms::others_write,
                  fs::perm_options::remove);
  const std::string command = unprivileged(systole() + " render " + quoted(ro.scene) + " -o " + quoted(ro.video));
  if (command.empty()) GTEST_SKIP() << "cannot drop root privileges here";
  expect_rejected(ro, run(command), 73, "is not writable");
  fs::permissions(ro.dir, fs::perms::owner_write, fs::perm_options::add);
}

TEST(InvalidInput, AVideoNameEndingInASlashIsRefusedNotMadeAFolder) {
  const Project p("output_video_slash", "organs: [{name: heart, mesh: {procedural: heart, detail: 1}}]\n" + kTiny);
  const RunResult r = run(systole() + " render " + quoted(p.scene) + " -o " + quoted(p.dir / "out" / "d.mp4") + "/");
  expect_rejected(p, r, 64, "'d.mp4' is a video's name; drop the '/'");
  EXPECT_FALSE(fs::exists(p.dir / "out")) << "no folder named after a video";
  // A folder that really is named so is still a folder.
  fs::create_directories(p.dir / "clips.mp4");
  const RunResult folder = run(systole() + " render " + quoted(p.scene) + " -o " + quoted(p.dir / "clips.mp4") + "/");
  EXPECT_EQ(folder.exit_code, 0) << folder.output;
  EXPECT_TRUE(fs::exists(p.dir / "clips.mp4" / "scene.mp4")) << folder.output;
}

TEST(InvalidInput, UnreadableSceneAndMeshAreNoInput) {
  const Project p("unreadable", mesh_scene("organ.obj"));
  write_file(p.dir / "organ.obj", tetrahedra(1, false, false));
  fs::permissions(p.dir / "organ.obj", fs::perms::none);
  const std::string mesh_command = unprivileged(systole() + " render " + quoted(p.scene) + " -o " + quoted(p.video));
  if (mesh_command.empty()) GTEST_SKIP() << "cannot drop root privileges here";
  fs::permissions(p.dir, fs::perms::all);  // The unprivileged user may write the clip here.
  expect_rejected(p, run(mesh_command), 66,
                  "organs[0].mesh.file: mesh file " + (p.dir / "organ.obj").string() + " is not readable (Permission denied)");
  fs::permissions(p.scene, fs::perms::none);
  expect_rejected(p, run(mesh_command), 66, "scene.yaml");
}

TEST(InvalidInput, PathsWithSpacesAndUnicodeWork) {
  const fs::path dir = scratch("invalid_unicode") / "my organs ♥" / "Herz ünd Lunge 心臓";
  fs::create_directories(dir);
  write_file(dir / "mein Gewebe é.obj", tetrahedra(1, false, false));
  const fs::path scene = dir / "szene mit Leerzeichen ✓.yaml";
  write_file(scene, mesh_scene("mein Gewebe é.obj"));
  const fs::path video = dir / "clip ♥.mp4";
  RunResult r = run(systole() + " render " + quoted(scene) + " -o " + quoted(video));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::is_regular_file(video)) << r.output;
  // An error names the path exactly as given.
  write_file(scene, mesh_scene("fehlt ü.obj"));
  r = run(systole() + " render " + quoted(scene) + " -o " + quoted(video));
  EXPECT_EQ(r.exit_code, 66) << r.output;
  EXPECT_NE(r.output.find((dir / "fehlt ü.obj").string()), std::string::npos) << r.output;
}

// --- Resource limits ----------------------------------------------------------------------------

TEST(InvalidInput, AbsurdRequestsAreRefusedBeforeWorkUnlessAllowed) {
  const std::string heart = "organs: [{name: heart, mesh: {procedural: heart, detail: 1}}]\n";
  {
    const Project p("limit_8k", heart + "output: {width: 7680, height: 4320, duration: 0.1 s}\n");
    expect_rejected(p, p.render(), 65, "output.width x output.height = 7680x4320 = 33177600 pixels is over the limit");
    EXPECT_NE(p.render().output.find("--allow-large"), std::string::npos);
    EXPECT_EQ(run(systole() + " validate --allow-large " + quoted(p.scene)).exit_code, 0);
  }
  {
    const Project p("limit_hour", heart + "output: {width: 64, height: 64, duration: 3600 s}\n");
    expect_rejected(p, p.render(), 65, "output.duration = 3600 s is over the limit of 600 s");
    EXPECT_EQ(run(systole() + " validate --allow-large " + quoted(p.scene)).exit_code, 0);
  }
  {
    const Project p("limit_steps", heart + "solver: {dt: 1e-6 s, substeps: 200}\noutput: {width: 64, height: 64, duration: 60 s}\n");
    expect_rejected(p, p.render(), 65, "substeps over the clip");
  }
  {
    const Project p("limit_png_size", heart + "output: {width: 3840, height: 2160, fps: 60, duration: 120 s}\n");
    expect_rejected(p, p.render("--no-video --png " + quoted(p.dir / "frames")), 65, "the estimated output size");
    EXPECT_FALSE(fs::exists(p.dir / "frames"));
  }
}

TEST(InvalidInput, VertexLimitIsCheckedBeforeTheFirstStep) {
  const scene::Scene scene =
      scene::load_from_string("organs: [{name: heart, mesh: {procedural: heart, detail: 1}}]\n", "limits.yaml");
  const world::World world = world::build_world(scene);
  clip::Limits limits;
  limits.max_vertices = 10;
  try {
    clip::check_world_limits(scene, world, limits);
    FAIL() << "expected the vertex limit";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kDataError);
    EXPECT_NE(std::string(e.what()).find("limits.yaml: the organs' "), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("vertices is over the limit of 10 vertices"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(clip::check_world_limits(scene, world, clip::Limits::none()));
  EXPECT_NO_THROW(clip::check_world_limits(scene, world, clip::Limits{}));
}

}  // namespace
}  // namespace systole::test

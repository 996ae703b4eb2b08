#include <iostream>
#include <memory>
#include <optional>

#include "cli/command.h"
#include "common/error.h"
#include "encode/png.h"
#include "plot/plot.h"
#include "scene/load.h"
#include "study/accuracy.h"

namespace systole::cli {
namespace {

/// What `systole bench` was given.
struct BenchArgs {
  std::string scene;
  std::vector<std::string> defines;
  std::string output;
  double duration_s = 0;
  std::vector<std::string> methods, dts;
  std::vector<int> substeps, lattices, iterations;
  std::string reference_method = "projective";
  std::string reference_dt = "1/960";
  int reference_substeps = 1;
  std::string check = "explicit:auto";
};

scene::SolverMethod parse_method(const std::string& m) {
  for (const auto method : {scene::SolverMethod::kProjective, scene::SolverMethod::kXpbd, scene::SolverMethod::kImplicit,
                            scene::SolverMethod::kExplicit}) {
    if (m == scene::method_name(method)) return method;
  }
  throw Error(ExitCode::kUsage, "expected a solver method (projective, xpbd, implicit, explicit); got '" + m + "'");
}

/// A step as "1/240", "0.004" (seconds) or "auto" (0: the solver's stable step).
double parse_step(const std::string& text) {
  try {
    if (text == "auto") return 0;
    const auto slash = text.find('/');
    std::size_t used = 0;
    double value = 0;
    if (slash == std::string::npos) {
      value = std::stod(text, &used);
      if (used != text.size()) throw std::invalid_argument(text);
    } else {
      const double num = std::stod(text.substr(0, slash), &used);
      if (used != slash) throw std::invalid_argument(text);
      const std::string den_text = text.substr(slash + 1);
      const double den = std::stod(den_text, &used);
      if (used != den_text.size() || den <= 0) throw std::invalid_argument(text);
      value = num / den;
    }
    if (!(value > 0 && value <= 1)) throw std::invalid_argument(text);
    return value;
  } catch (const std::logic_error&) {
    throw Error(ExitCode::kUsage, "--dt: expected a step in seconds such as 1/240 or 0.004, or auto; got '" + text + "'");
  }
}

/// The grid the --method, --dt, --substeps and --lattice lists narrow to (unnamed lists: their default).
std::vector<study::BenchConfig> narrowed_grid(const BenchArgs& o) {
  std::vector<scene::SolverMethod> methods;
  for (const auto& m : o.methods) methods.push_back(parse_method(m));
  if (methods.empty()) {
    methods = {scene::SolverMethod::kProjective, scene::SolverMethod::kXpbd, scene::SolverMethod::kImplicit};
  }
  std::vector<double> dts;
  for (const auto& d : o.dts) dts.push_back(parse_step(d));
  if (dts.empty()) dts = {1.0 / 60.0};
  return study::grid_of(methods, dts, o.substeps.empty() ? std::vector<int>{1} : o.substeps,
                        o.lattices.empty() ? std::vector<int>{0} : o.lattices,
                        o.iterations.empty() ? std::vector<int>{2} : o.iterations);
}

/// --check: "none", or METHOD:STEP[:SUBSTEPS] such as explicit:auto or implicit:1/960.
std::optional<study::BenchConfig> parse_check(const std::string& text) {
  if (text == "none") return std::nullopt;
  const auto first = text.find(':');
  if (first == std::string::npos) {
    throw Error(ExitCode::kUsage, "--check: expected none or METHOD:STEP[:SUBSTEPS] (explicit:auto); got '" + text + "'");
  }
  const auto second = text.find(':', first + 1);
  study::BenchConfig c;
  c.method = parse_method(text.substr(0, first));
  c.dt_s = parse_step(text.substr(first + 1, second == std::string::npos ? std::string::npos : second - first - 1));
  c.substeps = second == std::string::npos ? 1 : std::stoi(text.substr(second + 1));
  return c;
}

}  // namespace

Command add_bench_command(CLI::App& app) {
  auto o = std::make_shared<BenchArgs>();
  auto* cmd = app.add_subcommand("bench", "Speed versus error: run the scene's organs over solver x step x model "
                                          "configurations against a reference; print a table, write CSV and a plot.");
  cmd->add_option("scene", o->scene, "Scene file (YAML)")->required()->type_name(kSceneValue);
  add_define_option(*cmd, o->defines);
  cmd->add_option("-o,--output", o->output, "Prefix of the outputs: PREFIX.csv and PREFIX.png (default out/<scene>-bench)")
      ->type_name(kFileValue);
  cmd->add_option("--duration", o->duration_s, "Simulated seconds per run (default: whole beats covering 2 s)")
      ->check(CLI::Range(0.1, 60.0));
  cmd->add_option("--method", o->methods, "Narrow the grid: solvers (projective, xpbd, implicit, explicit)")
      ->check(CLI::IsMember({"projective", "xpbd", "implicit", "explicit"}))
      ->delimiter(',');
  cmd->add_option("--dt", o->dts, "Narrow the grid: steps (1/240, 0.004, auto)")->delimiter(',');
  cmd->add_option("--substeps", o->substeps, "Narrow the grid: substeps per step")->check(CLI::Range(1, 10000))->delimiter(',');
  cmd->add_option("--iterations", o->iterations, "Narrow the grid: projective iterations per step")
      ->check(CLI::Range(1, 50))
      ->delimiter(',');
  cmd->add_option("--lattice", o->lattices, "Narrow the grid: models (0 = full, N = lattice of N voxels along the longest side)")
      ->check(CLI::Range(0, 64))
      ->delimiter(',');
  cmd->add_option("--reference-method", o->reference_method, "Solver of the reference run (full model)")
      ->check(CLI::IsMember({"projective", "xpbd", "implicit", "explicit"}))
      ->capture_default_str();
  cmd->add_option("--reference-dt", o->reference_dt, "Step of the reference run (or auto); bench halves it to prove it")
      ->capture_default_str();
  cmd->add_option("--reference-substeps", o->reference_substeps, "Substeps of the reference run")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  cmd->add_option("--check", o->check,
                  "The second solver that must reach the reference's motion: METHOD:STEP[:SUBSTEPS], or none")
      ->capture_default_str();
  return {cmd, [o] {
            const auto scene = scene::load(o->scene, o->defines);
            study::BenchOptions options;
            options.duration_s = o->duration_s;
            options.reference.method = parse_method(o->reference_method);
            options.reference.dt_s = parse_step(o->reference_dt);
            options.reference.substeps = o->reference_substeps;
            options.check = parse_check(o->check);
            if (!o->methods.empty() || !o->dts.empty() || !o->substeps.empty() || !o->lattices.empty() ||
                !o->iterations.empty()) {
              options.grid = narrowed_grid(*o);
            }
            const study::BenchReport report =
                study::run_bench(scene, options, [](const std::string& run) { std::cerr << "bench: " << run << "\n"; });
            std::cout << study::format_table(report);
            const std::string prefix = o->output.empty() ? "out/" + scene.name + "-bench" : o->output;
            const std::filesystem::path csv = prefix + ".csv", png = prefix + ".png";
            if (csv.has_parent_path()) std::filesystem::create_directories(csv.parent_path());
            study::write_csv(csv, report);
            encode::write_png(png, plot::render(study::speed_error_figure(report)));
            std::cout << "wrote " << csv.string() << " and " << png.string() << "\n";
            return 0;
          }};
}

}  // namespace systole::cli

#include "train/report.h"

#include <fstream>
#include <cmath>
#include <sstream>

#include "chart/svg_chart.h"
#include "common/atomic_output.h"
#include "common/error.h"

namespace systole::train {

namespace {

std::string plot_name(const OrganTuning& t, const scene::Region& r) { return t.organ + "-" + r.name + ".svg"; }

std::string fixed(double v, int digits = 3) {
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(digits);
  s << v;
  return s.str();
}

/// A share in % with two decimals, or "-" when there is nothing it is a share of.
std::string share(double pct) { return std::isnan(pct) ? "-" : fixed(pct, 2); }

/// `pct` as a multiple of the floor's `floor_pct`, or "-" when the floor is 0 or unknown.
std::string times_floor(double pct, double floor_pct) {
  return std::isfinite(floor_pct) && floor_pct > 0 && !std::isnan(pct) ? fixed(pct / floor_pct, 2) : "-";
}

std::string error_row(const std::string& drives, const PlaybackError& e, const PlaybackError& floor) {
  return "| " + drives + " | " + fixed(e.rms_pct_of_motion, 2) + " | " + times_floor(e.rms_pct_of_motion, floor.rms_pct_of_motion) +
         " | " + fixed(e.rms_pct_of_diagonal) + " | " + fixed(e.max_pct_of_diagonal) + " | " + fixed(e.volume_percent) + " | " + fixed(e.mean_offset_pct_of_motion, 2) + " |\n";
}

void write_text(const std::filesystem::path& path, const std::string& text) {
  AtomicOutput out(path);
  {
    std::ofstream file(out.temp_path(), std::ios::binary);
    file << text;
    if (!file.flush()) throw Error(ExitCode::kIoError, "cannot write " + path.string());
  }
  out.commit();
}

// The free parameters, fitted and tuned (or why there is no tuned column).
std::string parameter_table(const OrganTuning& t) {
  if (t.kept_written) {
    return "\nThe search ended farther from the target than the drives as written, so the tuned scene keeps "
           "those; the table above gives them as tuned.\n\n";
  }
  std::ostringstream o;
  o << "\nTuned parameters:\n\n| parameter | fitted | tuned |\n|---|---|---|\n";
  for (const Parameter& p : t.parameters) {
    auto value = [&](const std::vector<scene::Region>& regions) {
      const scene::Region& reg = regions[p.region];
      switch (p.kind) {
        case Parameter::Kind::kAmplitude: return reg.drive.amplitude;
        case Parameter::Kind::kHarmonicAmplitude: return reg.drive.harmonics[p.harmonic].amplitude;
        case Parameter::Kind::kHarmonicPhase: return reg.drive.harmonics[p.harmonic].phase_rad;
        case Parameter::Kind::kDelay: return reg.drive.delay_s;
        case Parameter::Kind::kLogStiffness: return reg.stiffness_scale;
      }
      return 0.0;
    };
    const bool stiffness = p.kind == Parameter::Kind::kLogStiffness;
    o << "| " << p.name << (stiffness ? " (scale)" : "") << " | " << fixed(value(t.fitted), 4) << " | " << fixed(value(t.regions), 4) << " |\n";
  }
  o << "\n";
  return o.str();
}

}  // namespace

std::string report_markdown(const std::string& scene_path, const std::vector<OrganTuning>& tunings) {
  std::ostringstream o;
  o << "# Tuning report: " << scene_path << "\n\n"
    << "Errors are measured with the body running free (no coupling) over the measured cycles, "
       "after the settling ones, on the organ's render surface. The floor is the body tied to the target "
       "(the scene's coupling, drives as written): what this body reaches held to it; every figure is also given "
       "as a multiple of it. The RMS vertex error is a share of the target's RMS motion about its "
       "mean shape (an organ held still in that shape scores 100 %), per region of the region's; it is "
       "also given in % of the organ's bounding diagonal, with the largest vertex error. Volume error "
       "in % of the target's mean volume, phase of each region's size (first harmonic) in degrees. The "
       "mean-shape offset is the part of the RMS error that stays the same all cycle (each vertex's mean "
       "error); the rest, sqrt(RMS^2 - offset^2), is the error in the motion itself.\n\n";
  for (const OrganTuning& t : tunings) {
    o << "## " << t.organ << "\n\n"
      << "The target moves by " << fixed(1e3 * t.target_motion_m, 3) << " mm RMS about its mean shape.\n\n"
      << "| drives | RMS % of motion | x floor | RMS % of diagonal | max % of diagonal | volume % | mean-shape offset, % of motion |\n"
         "|---|---|---|---|---|---|---|\n"
      << "| held still in the target's mean shape | 100.00 | " << times_floor(100.0, t.floor.rms_pct_of_motion) << " | "
      << fixed(t.target_motion_pct_of_diagonal) << " | | | 0.00 |\n"
      << error_row("floor: tied to the target (" + fixed(t.coupling_N_per_m, 0) + " N/m)", t.floor, t.floor)
      << error_row("as written", t.written, t.floor)
      << error_row("fitted from forces (untuned)", t.fitted_from_forces, t.floor)
      << error_row("fitted from lengths (untuned)", t.fitted_from_lengths, t.floor) << error_row("tuned", t.after, t.floor)
      << error_row("tuned, at half the step", t.after_half_step, t.floor)
      << "\n"
      << t.parameters.size() << " free parameters, searched from the fit from " << t.start_from << "; " << t.generations
      << " CMA-ES generations, " << t.evaluations << " playbacks, " << fixed(t.seconds, 1)
      << " s wall time; stopped: " << t.stop_reason << ". Mean coupling force while recording: "
      << fixed(t.mean_coupling_force_N, 5) << " N per particle.\n\n";
    if (!t.transfer.empty()) o << t.transfer << "\n\n";
    o << "| region | floor, RMS % of its motion | fitted | tuned | tuned x floor | phase deg fitted | phase deg tuned | plot |\n"
         "|---|---|---|---|---|---|---|---|\n";
    for (std::size_t r = 0; r < t.regions.size(); ++r) {
      const scene::Region& region = t.regions[r];
      if (region.pinned) continue;
      o << "| " << region.name << " | " << share(t.floor.regions[r].rms_pct_of_motion) << " | "
        << share(t.before.regions[r].rms_pct_of_motion) << " | " << share(t.after.regions[r].rms_pct_of_motion) << " | "
        << times_floor(t.after.regions[r].rms_pct_of_motion, t.floor.regions[r].rms_pct_of_motion) << " | "
        << fixed(t.before.regions[r].phase_deg, 1) << " | " << fixed(t.after.regions[r].phase_deg, 1) << " | ![" << region.name << "]("
        << plot_name(t, region) << ") |\n";
    }
    o << parameter_table(t);
  }
  return o.str();
}

void write_report(const std::filesystem::path& dir, const std::string& scene_path, const std::vector<OrganTuning>& tunings) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw Error(ExitCode::kCannotCreate, "cannot create the report folder " + dir.string() + ": " + ec.message());
  for (const OrganTuning& t : tunings) {
    for (std::size_t r = 0; r < t.regions.size(); ++r) {
      if (t.regions[r].pinned) continue;
      std::vector<double> time;
      for (std::size_t k = 0; k < t.target_size[r].size(); ++k) time.push_back(t.measure_start_s + double(k) * t.dt_s);
      const std::vector<chart::SvgSeries> series = {
          {"target", "#222222", false, t.target_size[r]},
          {"floor (tied to the target)", "#7f8c8d", true, t.floor.size[r]},
          {"fitted (untuned)", "#e08a2c", true, t.before.size[r]},
          {"tuned", "#c0392b", false, t.after.size[r]},
      };
      write_text(dir / plot_name(t, t.regions[r]),
                 chart::svg_line_chart(t.organ + " / " + t.regions[r].name + ": region size", "time [s]", "size relative to rest", time, series));
    }
  }
  write_text(dir / "report.md", report_markdown(scene_path, tunings));
}

}  // namespace systole::train

#include <iostream>
#include <memory>

#include "cli/command.h"
#include "common/error.h"
#include "encode/png.h"
#include "study/compare.h"

namespace systole::cli {

Command add_compare_command(CLI::App& app) {
  struct Options {
    std::string actual, reference, diff;
    study::CompareTolerance tolerance;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "compare", "Compare two PNG images per channel: exit 0 when within the tolerances, 1 when they differ.");
  cmd->add_option("actual", o->actual, "The image to check (PNG)")->required()->type_name(kFileValue);
  cmd->add_option("reference", o->reference, "The reference image (PNG)")->required()->type_name(kFileValue);
  cmd->add_option("--max-delta", o->tolerance.max_delta,
                  "A pixel is over when a channel differs by more than this (0-255)")
      ->capture_default_str()
      ->check(CLI::Range(0, 255));
  cmd->add_option("--max-percent", o->tolerance.max_percent, "Percentage of pixels allowed over --max-delta")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 100.0));
  cmd->add_option("--diff", o->diff, "When they differ, write actual | reference | amplified difference here")
      ->type_name(kFileValue);

  return {cmd, [o] {
            const Image actual = encode::read_png(o->actual);
            const Image reference = encode::read_png(o->reference);
            const auto result = study::compare_images(actual, reference, o->tolerance);
            std::cout << study::describe(result, o->tolerance);
            if (result.passed) return static_cast<int>(ExitCode::kOk);
            if (!o->diff.empty()) {
              encode::write_png(o->diff, study::difference_image(actual, reference));
              std::cout << "wrote " << o->diff << " (actual | reference | amplified difference)\n";
            }
            return static_cast<int>(ExitCode::kDiffers);
          }};
}

}  // namespace systole::cli

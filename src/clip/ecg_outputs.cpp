#include "clip/ecg_outputs.h"

#include "electro/ecg_files.h"
#include "encode/png.h"
#include "overlay/ecg_sheet.h"
#include "world/heart_ecg.h"

namespace systole::clip {
namespace {

/// The still's width: 5 px a millimetre of the sheet, fine enough for its 1-mm grid. unit: px
constexpr int kSheetWidthPx = 1340;

std::filesystem::path with_suffix(const std::filesystem::path& video, const std::string& middle, const char* ext) {
  std::filesystem::path p = video;
  p.replace_extension();
  p += middle + ext;
  return p;
}

}  // namespace

EcgFiles ecg_files_beside(const std::filesystem::path& video, const std::string& organ, bool several) {
  const std::string middle = several ? "." + organ : "";
  return {with_suffix(video, middle, ".ecg.csv"), with_suffix(video, middle, ".edf"),
          with_suffix(video, middle, ".ecg.png")};
}

std::vector<std::filesystem::path> write_ecg_outputs(const world::World& world, const std::filesystem::path& video,
                                                     double clip_s) {
  int excited = 0;
  for (const world::OrganBody& body : world.organs) excited += body.model.excitation != nullptr;
  std::vector<std::filesystem::path> written;
  for (const world::OrganBody& body : world.organs) {
    const std::optional<electro::Ecg> ecg = world::organ_ecg(body, clip_s);
    if (!ecg || ecg->samples() == 0) continue;
    const EcgFiles files = ecg_files_beside(video, body.model.name, excited > 1);
    electro::write_ecg_csv(*ecg, files.csv);
    electro::EdfInfo info;
    info.patient = body.model.name;
    info.recording = video.filename().string();
    electro::write_ecg_edf(*ecg, files.edf, info);
    const overlay::EcgSheet sheet{"Systole: computed 12-lead ECG of " + body.model.name, ecg->rate_hz, ecg->start_s,
                                  ecg->leads, ecg->mv};
    plot::Font font;
    encode::write_png(files.sheet, overlay::ecg_sheet_still(sheet, font, kSheetWidthPx));
    written.insert(written.end(), {files.csv, files.edf, files.sheet});
  }
  return written;
}

}  // namespace systole::clip

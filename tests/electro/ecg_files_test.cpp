// The ECG's files: CSV values, EDF+ bytes where the spec puts them, the round trip through
// our reader and through MNE-Python's (the client most users will open them with), and
// failed writes that leave nothing behind.

#include "electro/ecg_files.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "support/error_code.h"
#include "support/run.h"
#include "support/small_disk.h"

namespace systole::test {
namespace {

namespace fs = std::filesystem;
using electro::Ecg;

constexpr double kPi = 3.14159265358979323846;

/// A 12-lead ECG of `duration_s` at `rate_hz`: per lead a QRS-like Gaussian bump each beat
/// (72 bpm), a T wave and a slow sine, of about 1 mV, a different mix (and sign) per lead.
Ecg synthetic_ecg(double duration_s = 3.3, double rate_hz = 500) {
  Ecg ecg;
  ecg.rate_hz = rate_hz;
  ecg.leads = electro::standard_leads();
  const auto n = static_cast<std::size_t>(std::llround(duration_s * rate_hz));
  for (std::size_t l = 0; l < ecg.leads.size(); ++l) {
    const double gain = (l == 3 ? -1.0 : 1.0) * (0.6 + 0.1 * static_cast<double>(l));
    std::vector<double> mv(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double t = static_cast<double>(i) / rate_hz;
      const double phase = std::fmod(t, 60.0 / 72);  // [s] into the beat
      const double qrs = std::exp(-std::pow((phase - 0.2) / 0.012, 2));
      const double wave_t = 0.3 * std::exp(-std::pow((phase - 0.5) / 0.05, 2));
      mv[i] = gain * (qrs + wave_t) + 0.05 * std::sin(2 * kPi * 0.3 * t + static_cast<double>(l));
    }
    ecg.mv.push_back(std::move(mv));
  }
  return ecg;
}

/// The largest error a value may carry through EDF: half the quantisation step of a lead
/// whose range is rounded up from its peak by at most 1e-5 mV (physical_limit's decimal).
double half_step_mv(const std::vector<double>& lead) {
  double peak = 0;
  for (const double v : lead) peak = std::max(peak, std::abs(v));
  return (2 * (peak + 1e-5) / 65535) / 2 + 1e-12;
}

/// The trimmed ASCII header field of `width` bytes at `at`.
std::string field(const std::string& bytes, std::size_t at, std::size_t width) {
  std::string out = bytes.substr(at, width);
  out.erase(out.find_last_not_of(' ') + 1);
  return out;
}

/// The 16-bit little-endian sample at byte `at`.
int sample_at(const std::string& bytes, std::size_t at) {
  const auto lo = static_cast<unsigned char>(bytes[at]), hi = static_cast<unsigned char>(bytes[at + 1]);
  return static_cast<std::int16_t>(static_cast<std::uint16_t>(lo | (hi << 8)));
}

/// The names in `dir`, sorted.
std::vector<std::string> entries(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// Layout of a file of 12 leads + annotations at 500 Hz: 13 signals, 256 bytes each plus 256.
constexpr std::size_t kSignals = 13;
constexpr std::size_t kHeaderBytes = 256 * (kSignals + 1);
constexpr std::size_t kPerRecord = 500;

/// The comma-separated cells of a CSV row.
std::vector<std::string> cells(const std::string& row) {
  std::vector<std::string> out;
  std::istringstream in(row);
  for (std::string cell; std::getline(in, cell, ',');) out.push_back(cell);
  return out;
}

TEST(EcgFiles, CsvHasAHeaderARowPerSampleAndMicrovoltValues) {
  const auto dir = scratch("ecg_csv");
  Ecg ecg = synthetic_ecg();
  ecg.start_s = 0.25;
  ecg.mv[1][3] = -1.23456;  // Rounds to -1.2346 at 4 decimals.
  ecg.mv[0][0] = -0.00001;  // Rounds to zero: written "0.0000", not "-0.0000".
  electro::write_ecg_csv(ecg, dir / "ecg.csv");
  std::istringstream in(read_file(dir / "ecg.csv"));
  std::vector<std::string> rows;
  for (std::string line; std::getline(in, line);) rows.push_back(line);
  ASSERT_EQ(rows.size(), 1 + ecg.samples());
  EXPECT_EQ(rows[0], "time_s,I,II,III,aVR,aVL,aVF,V1,V2,V3,V4,V5,V6");
  EXPECT_EQ(cells(rows[1])[0], "0.250000");
  EXPECT_EQ(cells(rows[1])[1], "0.0000");
  EXPECT_EQ(cells(rows[4])[0], "0.256000");
  EXPECT_EQ(cells(rows[4])[2], "-1.2346");
  for (const std::size_t i : {std::size_t{100}, std::size_t{777}, ecg.samples() - 1}) {
    const auto row = cells(rows[i + 1]);
    ASSERT_EQ(row.size(), 13u) << "row " << i;
    EXPECT_NEAR(std::stod(row[0]), 0.25 + static_cast<double>(i) / 500, 5e-7);
    for (std::size_t l = 0; l < 12; ++l) {
      // Half the last decimal: exact to 0.05 uV.
      EXPECT_NEAR(std::stod(row[l + 1]), ecg.mv[l][i], 5e-5 + 1e-12) << "row " << i << " lead " << ecg.leads[l];
    }
  }
}

TEST(EcgFiles, EdfReadsBackWithinHalfAQuantisationStep) {
  const auto dir = scratch("ecg_edf_round_trip");
  const Ecg ecg = synthetic_ecg();  // 3.3 s: the fourth record is partial.
  electro::write_ecg_edf(ecg, dir / "ecg.edf");
  const Ecg back = electro::read_ecg_edf(dir / "ecg.edf");
  EXPECT_EQ(back.rate_hz, 500);
  EXPECT_EQ(back.leads, ecg.leads);
  ASSERT_EQ(back.mv.size(), 12u);
  ASSERT_EQ(back.samples(), 1650u) << "the padding is dropped";
  for (std::size_t l = 0; l < 12; ++l) {
    const double tolerance = half_step_mv(ecg.mv[l]);
    double worst = 0;
    for (std::size_t i = 0; i < ecg.samples(); ++i) worst = std::max(worst, std::abs(back.mv[l][i] - ecg.mv[l][i]));
    EXPECT_LE(worst, tolerance) << "lead " << ecg.leads[l];
  }
}

TEST(EcgFiles, EdfThatFillsItsRecordsReadsBackWhole) {
  const auto dir = scratch("ecg_edf_whole");
  const Ecg ecg = synthetic_ecg(2.0, 250);
  electro::write_ecg_edf(ecg, dir / "ecg.edf");
  const std::string bytes = read_file(dir / "ecg.edf");
  EXPECT_EQ(bytes.find("BAD_padding"), std::string::npos) << "nothing is padded";
  const Ecg back = electro::read_ecg_edf(dir / "ecg.edf");
  EXPECT_EQ(back.rate_hz, 250);
  ASSERT_EQ(back.samples(), 500u);
  EXPECT_NEAR(back.mv[5][123], ecg.mv[5][123], half_step_mv(ecg.mv[5]));
}

TEST(EcgFiles, EdfHeaderFieldsSitAtTheirByteOffsets) {
  const auto dir = scratch("ecg_edf_header");
  electro::EdfInfo info;
  info.start = {2024, 3, 7, 14, 5, 9};
  info.patient = "heart demo";
  info.recording = "heart.yaml";
  const Ecg ecg = synthetic_ecg();
  electro::write_ecg_edf(ecg, dir / "ecg.edf", info);
  const std::string b = read_file(dir / "ecg.edf");
  // Main header (EDF spec, table 1).
  EXPECT_EQ(b.substr(0, 8), "0       ");
  EXPECT_EQ(field(b, 8, 80), "X X X heart_demo");
  EXPECT_EQ(field(b, 88, 80), "Startdate 07-MAR-2024 heart.yaml X Systole");
  EXPECT_EQ(b.substr(168, 8), "07.03.24");
  EXPECT_EQ(b.substr(176, 8), "14.05.09");
  EXPECT_EQ(field(b, 184, 8), std::to_string(kHeaderBytes));
  EXPECT_EQ(field(b, 192, 44), "EDF+C");
  EXPECT_EQ(field(b, 236, 8), "4") << "3.3 s in 1 s records";
  EXPECT_EQ(field(b, 244, 8), "1");
  EXPECT_EQ(field(b, 252, 4), "13");
  // Signal headers: each field for all 13 signals in turn.
  const std::size_t labels = 256, dimensions = labels + 13 * (16 + 80), physical_min = dimensions + 13 * 8;
  const std::size_t physical_max = physical_min + 13 * 8, digital_min = physical_max + 13 * 8;
  const std::size_t digital_max = digital_min + 13 * 8, prefilter = digital_max + 13 * 8;
  const std::size_t samples = prefilter + 13 * 80;
  EXPECT_EQ(b.substr(labels, 16), "ECG I           ");
  EXPECT_EQ(field(b, labels + 3 * 16, 16), "ECG aVR");
  EXPECT_EQ(field(b, labels + 11 * 16, 16), "ECG V6");
  EXPECT_EQ(b.substr(labels + 12 * 16, 16), "EDF Annotations ");
  EXPECT_EQ(field(b, labels + 13 * 16, 80), "") << "transducer";
  EXPECT_EQ(field(b, dimensions, 8), "mV");
  for (std::size_t s = 0; s < 12; ++s) {
    const double low = std::stod(field(b, physical_min + 8 * s, 8)), high = std::stod(field(b, physical_max + 8 * s, 8));
    double peak = 0;
    for (const double v : ecg.mv[s]) peak = std::max(peak, std::abs(v));
    EXPECT_EQ(low, -high) << "symmetric, signal " << s;
    EXPECT_GE(high, peak) << "holds every sample, signal " << s;
    EXPECT_LE(high, peak + 1e-5) << "rounded at the field's last decimal, signal " << s;
    EXPECT_EQ(field(b, digital_min + 8 * s, 8), "-32768");
    EXPECT_EQ(field(b, digital_max + 8 * s, 8), "32767");
    EXPECT_EQ(field(b, prefilter + 80 * s, 80), "");
    EXPECT_EQ(field(b, samples + 8 * s, 8), "500");
  }
  const std::size_t annotation_samples = std::stoul(field(b, samples + 8 * 12, 8));
  EXPECT_EQ(b.size(), kHeaderBytes + 4 * (2 * (12 * kPerRecord + annotation_samples)));
}

TEST(EcgFiles, EdfAnnotationsKeepTimeAndMarkThePadding) {
  const auto dir = scratch("ecg_edf_annotations");
  const Ecg ecg = synthetic_ecg();
  electro::write_ecg_edf(ecg, dir / "ecg.edf");
  const std::string b = read_file(dir / "ecg.edf");
  const std::size_t annotation_bytes = 2 * std::stoul(field(b, 256 + 13 * 216 + 12 * 8, 8));
  const std::size_t record_bytes = 2 * 12 * kPerRecord + annotation_bytes;
  for (std::size_t k = 0; k < 4; ++k) {
    const std::string tals = b.substr(kHeaderBytes + k * record_bytes + 2 * 12 * kPerRecord, annotation_bytes);
    const std::string keeping = "+" + std::to_string(k) + "\x14\x14" + std::string(1, '\0');
    EXPECT_EQ(tals.substr(0, keeping.size()), keeping) << "record " << k;
    if (k < 3) {
      EXPECT_EQ(tals.find_first_not_of('\0', keeping.size()), std::string::npos) << "only time, record " << k;
    }
  }
  const std::string last = b.substr(kHeaderBytes + 3 * record_bytes + 2 * 12 * kPerRecord, annotation_bytes);
  const std::string padding = std::string("+3.3\x15") + "0.7\x14" + "BAD_padding\x14" + std::string(1, '\0');
  EXPECT_EQ(last.substr(5, padding.size()), padding);
  // The padded samples repeat each lead's last one: the last record's 150th..500th of lead II.
  const std::size_t lead_ii = kHeaderBytes + 3 * record_bytes + 2 * kPerRecord;
  EXPECT_NE(sample_at(b, lead_ii + 2 * 148), sample_at(b, lead_ii + 2 * 149)) << "real data before the end";
  for (std::size_t i = 150; i < kPerRecord; ++i) EXPECT_EQ(sample_at(b, lead_ii + 2 * i), sample_at(b, lead_ii + 2 * 149));
}

TEST(EcgFiles, EdfRefusesWhatItCannotHoldAndWritesNothing) {
  const auto dir = scratch("ecg_edf_refused");
  Ecg odd_rate = synthetic_ecg(1.0, 333.3);
  EXPECT_EQ(code_of([&] { electro::write_ecg_edf(odd_rate, dir / "a.edf"); }), ExitCode::kDataError);
  EXPECT_NE(message_of([&] { electro::write_ecg_edf(odd_rate, dir / "a.edf"); }).find("whole number of Hz"),
            std::string::npos);
  electro::EdfInfo late;
  late.start.year = 2090;
  EXPECT_EQ(code_of([&] { electro::write_ecg_edf(synthetic_ecg(1.0), dir / "b.edf", late); }), ExitCode::kDataError);
  electro::EdfInfo feb30;
  feb30.start = {2023, 2, 29, 0, 0, 0};
  EXPECT_EQ(code_of([&] { electro::write_ecg_edf(synthetic_ecg(1.0), dir / "b.edf", feb30); }), ExitCode::kDataError);
  Ecg ragged = synthetic_ecg(1.0);
  ragged.mv[4].pop_back();
  EXPECT_EQ(code_of([&] { electro::write_ecg_edf(ragged, dir / "c.edf"); }), ExitCode::kInternal);
  EXPECT_EQ(code_of([&] { electro::write_ecg_csv(ragged, dir / "c.csv"); }), ExitCode::kInternal);
  Ecg not_finite = synthetic_ecg(1.0);
  not_finite.mv[2][7] = std::nan("");
  EXPECT_EQ(code_of([&] { electro::write_ecg_edf(not_finite, dir / "d.edf"); }), ExitCode::kInternal);
  EXPECT_EQ(code_of([&] { electro::write_ecg_edf(Ecg{}, dir / "e.edf"); }), ExitCode::kInternal);
  EXPECT_TRUE(entries(dir).empty());
}

TEST(EcgFiles, AFailedWriteLeavesNoFileAndTheEarlierOneUntouched) {
  const auto dir = scratch("ecg_failed_write");
  const Ecg ecg = synthetic_ecg(1.0);
  // A folder that does not exist.
  EXPECT_EQ(code_of([&] { electro::write_ecg_edf(ecg, dir / "missing" / "ecg.edf"); }), ExitCode::kCannotCreate);
  EXPECT_EQ(code_of([&] { electro::write_ecg_csv(ecg, dir / "missing" / "ecg.csv"); }), ExitCode::kCannotCreate);
  EXPECT_FALSE(fs::exists(dir / "missing"));
  // A target that is a folder: the data is written, the final rename fails.
  fs::create_directory(dir / "taken.edf");
  EXPECT_NE(code_of([&] { electro::write_ecg_edf(ecg, dir / "taken.edf"); }), ExitCode::kOk);
  EXPECT_TRUE(fs::is_directory(dir / "taken.edf"));
  EXPECT_TRUE(fs::is_empty(dir / "taken.edf"));
  EXPECT_EQ(entries(dir), std::vector<std::string>{"taken.edf"}) << "no temporary or lock file left";
}

TEST(EcgFiles, ADiskFullHalfWayKeepsTheEarlierFile) {
  const SmallDisk disk(scratch("ecg_full_disk") / "disk", "64k");
  if (!disk.mounted) GTEST_SKIP() << kNoSmallDisk;
  electro::write_ecg_edf(synthetic_ecg(1.0), disk.dir / "ecg.edf");  // About 16 kB.
  const std::string earlier = read_file(disk.dir / "ecg.edf");
  // 10 s, about 124 kB: the disk fills part-way through the records.
  EXPECT_EQ(code_of([&] { electro::write_ecg_edf(synthetic_ecg(10.0), disk.dir / "ecg.edf"); }), ExitCode::kIoError);
  EXPECT_EQ(read_file(disk.dir / "ecg.edf"), earlier);
  EXPECT_EQ(entries(disk.dir), std::vector<std::string>{"ecg.edf"}) << "no temporary or lock file left";
}

TEST(EcgFiles, TheReaderNamesTheFileAndWhatIsWrong) {
  const auto dir = scratch("ecg_edf_malformed");
  electro::write_ecg_edf(synthetic_ecg(2.5), dir / "good.edf");
  const std::string good = read_file(dir / "good.edf");
  const auto error_for = [&](const std::string& name, const std::string& bytes) {
    write_file(dir / name, bytes);
    EXPECT_EQ(code_of([&] { electro::read_ecg_edf(dir / name); }), ExitCode::kDataError) << name;
    return message_of([&] { electro::read_ecg_edf(dir / name); });
  };
  const std::string truncated = error_for("truncated.edf", good.substr(0, good.size() - 10));
  EXPECT_NE(truncated.find((dir / "truncated.edf").string()), std::string::npos) << truncated;
  EXPECT_NE(truncated.find("header announces"), std::string::npos) << truncated;
  EXPECT_NE(error_for("long.edf", good + "xy").find("header announces"), std::string::npos);
  EXPECT_NE(error_for("short.edf", good.substr(0, 100)).find("ends inside the header"), std::string::npos);
  std::string plain = good;
  plain.replace(192, 5, "     ");
  EXPECT_NE(error_for("plain.edf", plain).find("EDF+C"), std::string::npos);
  std::string version = good;
  version[0] = '1';
  EXPECT_NE(error_for("version.edf", version).find("version"), std::string::npos);
  // Record 2's time-keeping TAL says +5 instead of +1.
  std::string jump = good;
  const std::size_t annotation_bytes = 2 * std::stoul(field(good, 256 + 13 * 216 + 12 * 8, 8));
  jump[kHeaderBytes + (2 * 12 * kPerRecord + annotation_bytes) + 2 * 12 * kPerRecord + 1] = '5';
  EXPECT_NE(error_for("jump.edf", jump).find("data record 2 starts at 5.000000 s"), std::string::npos);
  EXPECT_EQ(code_of([&] { electro::read_ecg_edf(dir / "absent.edf"); }), ExitCode::kNoInput);
}

/// Reads an EDF with MNE-Python and prints what it found: sfreq, channel names, sample
/// count, each annotation, the names and types MNE infers from EDF+ labels ("ECG I" is
/// type ECG, name I), then the data in mV, one row per sample.
constexpr const char* kMneScript = R"(import sys
import mne
raw = mne.io.read_raw_edf(sys.argv[1], preload=True, verbose="error")
print("sfreq", raw.info["sfreq"])
print("names", ",".join(raw.ch_names))
print("samples", raw.n_times)
for a in raw.annotations:
    print("annotation", a["onset"], a["duration"], a["description"])
typed = mne.io.read_raw_edf(sys.argv[1], infer_types=True, verbose="error")
print("typed", ",".join(typed.ch_names), ",".join(sorted(set(typed.get_channel_types()))))
for row in (raw.get_data() * 1e3).T:  # volts to mV
    print(" ".join("%.9f" % v for v in row))
)";

TEST(EcgFiles, MneReadsTheEdfAsWritten) {
  if (std::system("/usr/bin/python3 -c 'import mne' >/dev/null 2>&1") != 0) {
    GTEST_SKIP() << "MNE-Python is not importable by /usr/bin/python3: install python3-mne (scripts/install-deps) "
                    "to check our EDF+ against the reader most users open it with";
  }
  const auto dir = scratch("ecg_edf_mne");
  const Ecg ecg = synthetic_ecg();
  electro::write_ecg_edf(ecg, dir / "ecg.edf");
  write_file(dir / "read.py", kMneScript);
  const RunResult r = run("/usr/bin/python3 " + (dir / "read.py").string() + " " + (dir / "ecg.edf").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::istringstream out(r.output);
  std::string line;
  std::getline(out, line);
  EXPECT_EQ(line, "sfreq 500.0");
  std::getline(out, line);
  EXPECT_EQ(line, "names ECG I,ECG II,ECG III,ECG aVR,ECG aVL,ECG aVF,ECG V1,ECG V2,ECG V3,ECG V4,ECG V5,ECG V6");
  std::getline(out, line);
  EXPECT_EQ(line, "samples 2000") << "MNE reads the padding as samples";
  std::getline(out, line);
  EXPECT_EQ(line, "annotation 3.3 0.7 BAD_padding");
  std::getline(out, line);
  EXPECT_EQ(line, "typed I,II,III,aVR,aVL,aVF,V1,V2,V3,V4,V5,V6 ecg");
  std::vector<std::vector<double>> rows;
  for (std::vector<double> row(12); out >> row[0];) {
    for (std::size_t l = 1; l < 12; ++l) out >> row[l];
    rows.push_back(row);
  }
  ASSERT_EQ(rows.size(), 2000u);
  for (std::size_t l = 0; l < 12; ++l) {
    const double tolerance = half_step_mv(ecg.mv[l]) + 1e-9;  // + the 9 decimals printed
    double worst = 0;
    for (std::size_t i = 0; i < 2000; ++i) {
      worst = std::max(worst, std::abs(rows[i][l] - ecg.mv[l][std::min<std::size_t>(i, 1649)]));
    }
    EXPECT_LE(worst, tolerance) << "lead " << ecg.leads[l] << " (padding repeats the last sample)";
  }
}

}  // namespace
}  // namespace systole::test

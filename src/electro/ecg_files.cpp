#include "electro/ecg_files.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <ostream>
#include <string_view>
#include <vector>

#include "common/atomic_output.h"
#include "common/error.h"
#include "common/input_file.h"

namespace systole::electro {
namespace fs = std::filesystem;
namespace {

constexpr int kDigitalMin = -32768;
constexpr int kDigitalMax = 32767;
constexpr double kRecordS = 1.0;  // The data record's duration. unit: s
constexpr std::size_t kFieldWidth = 8;  // The width of EDF's numeric header fields.
constexpr std::string_view kAnnotationLabel = "EDF Annotations";
constexpr std::string_view kLeadPrefix = "ECG ";
// MNE leaves spans whose annotation starts with "BAD" out of epochs and averages.
constexpr std::string_view kPaddingText = "BAD_padding";
constexpr char kTalOnsetEnd = '\x15';  // Between a TAL's onset and its duration.
constexpr char kTalTextEnd = '\x14';   // After the onset (and duration), and after each text.

/// `value` with `decimals` decimals, as printf's %.Nf writes it.
std::string fixed(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

/// Stops on an ECG that its own producer should never have made: the leads disagree in
/// number or length, or a sample is not a number.
void check_consistent(const Ecg& ecg) {
  if (ecg.mv.size() != ecg.leads.size()) {
    throw Error(ExitCode::kInternal, "ECG has " + std::to_string(ecg.leads.size()) + " lead names but " +
                                         std::to_string(ecg.mv.size()) + " sample series");
  }
  for (std::size_t l = 0; l < ecg.mv.size(); ++l) {
    if (ecg.mv[l].size() != ecg.samples()) {
      throw Error(ExitCode::kInternal, "ECG lead " + ecg.leads[l] + " has " + std::to_string(ecg.mv[l].size()) +
                                           " samples, lead " + ecg.leads[0] + " " + std::to_string(ecg.samples()));
    }
    const auto bad = std::find_if(ecg.mv[l].begin(), ecg.mv[l].end(), [](double v) { return !std::isfinite(v); });
    if (bad != ecg.mv[l].end()) {
      throw Error(ExitCode::kInternal, "ECG lead " + ecg.leads[l] + " sample " +
                                           std::to_string(bad - ecg.mv[l].begin()) + " is not finite");
    }
  }
  if (!(ecg.rate_hz > 0) || !std::isfinite(ecg.rate_hz)) {
    throw Error(ExitCode::kInternal, "ECG rate " + std::to_string(ecg.rate_hz) + " Hz is not a positive number");
  }
}

// ---------------------------------------------------------------------------------------
// CSV

/// A CSV cell: `value` with `decimals` decimals, never "-0.0000" for a value that rounds to 0.
std::string csv_cell(double value, int decimals) {
  const double unit = std::pow(10.0, -decimals);
  return fixed(std::abs(value) < unit / 2 ? 0.0 : value, decimals);
}

}  // namespace

void write_ecg_csv(const Ecg& ecg, const fs::path& file) {
  check_consistent(ecg);
  write_atomically(file, [&](std::ostream& out) {
    out << "time_s";
    for (const auto& name : ecg.leads) out << ',' << name;
    out << '\n';
    for (std::size_t i = 0; i < ecg.samples(); ++i) {
      out << csv_cell(ecg.start_s + static_cast<double>(i) / ecg.rate_hz, 6);
      for (const auto& lead : ecg.mv) out << ',' << csv_cell(lead[i], 4);
      out << '\n';
    }
  });
}

namespace {

// ---------------------------------------------------------------------------------------
// EDF+ writing

/// One signal's header entries (the spec's per-signal fields, in its order).
struct SignalHeader {
  std::string label;
  std::string dimension;  // Physical unit.
  std::string physical_min, physical_max;  // As written; the writer scales by these texts.
  int samples_per_record = 0;
};

/// `text` left-aligned in a field of `width` characters, space-filled.
std::string field(std::string text, std::size_t width) {
  text.resize(width, ' ');
  return text;
}

/// An EDF+ identification subfield: printable ASCII without spaces, "X" when empty, at
/// most `width` characters.
std::string subfield(const std::string& text, std::size_t width) {
  std::string out;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    out += byte > ' ' && byte < 127 ? c : '_';
  }
  if (out.empty()) out = "X";
  return out.substr(0, width);
}

/// The sampling rate as a whole number of samples per record; throws for any other rate.
int samples_per_record(double rate_hz) {
  const double per_record = rate_hz * kRecordS;
  if (!(per_record >= 1) || per_record > 99999999 || per_record != std::round(per_record)) {
    throw Error(ExitCode::kDataError,
                "ECG rate " + fixed(rate_hz, 6) + " Hz cannot be written as EDF: its 1 s data records need a "
                "whole number of samples, so the rate must be a whole number of Hz (e.g. 500 Hz)");
  }
  return static_cast<int>(per_record);
}

/// Throws unless `t` is a date and time EDF's header can name (years 1985-2084).
void check_start(const EdfDateTime& t) {
  static constexpr int kDays[] = {31, 29, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  const bool leap = (t.year % 4 == 0 && t.year % 100 != 0) || t.year % 400 == 0;
  const bool date_ok = t.year >= 1985 && t.year <= 2084 && t.month >= 1 && t.month <= 12 && t.day >= 1 &&
                       t.day <= kDays[t.month - 1] - (t.month == 2 && !leap ? 1 : 0);
  const bool time_ok = t.hour >= 0 && t.hour < 24 && t.minute >= 0 && t.minute < 60 && t.second >= 0 && t.second < 60;
  if (!date_ok || !time_ok) {
    char text[96];
    std::snprintf(text, sizeof text, "%04d-%02d-%02d %02d:%02d:%02d", t.year, t.month, t.day, t.hour, t.minute,
                  t.second);
    throw Error(ExitCode::kDataError, std::string("EDF start ") + text +
                                          " is not a valid date and time between 1985 and 2084 (EDF's header "
                                          "gives the year in two digits)");
  }
}

/// The 256-byte main header.
std::string main_header(const EdfInfo& info, std::size_t signals, std::size_t records) {
  static constexpr const char* kMonths[] = {"JAN", "FEB", "MAR", "APR", "MAY", "JUN",
                                            "JUL", "AUG", "SEP", "OCT", "NOV", "DEC"};
  const EdfDateTime& t = info.start;
  char date[32], time[32], startdate[32];
  std::snprintf(date, sizeof date, "%02d.%02d.%02d", t.day, t.month, t.year % 100);
  std::snprintf(time, sizeof time, "%02d.%02d.%02d", t.hour, t.minute, t.second);
  std::snprintf(startdate, sizeof startdate, "%02d-%s-%04d", t.day, kMonths[t.month - 1], t.year);
  // EDF+ subfields: patient "code sex birthdate name", recording "Startdate <date>
  // admincode technician equipment"; "X" marks each one a simulation does not know.
  const std::string patient = "X X X " + subfield(info.patient, 80 - 6);
  const std::string recording_start = std::string("Startdate ") + startdate + " ";
  const std::string recording_end = " X Systole";  // technician unknown; equipment
  const std::string recording =
      recording_start + subfield(info.recording, 80 - recording_start.size() - recording_end.size()) + recording_end;
  return field("0", 8) + field(patient, 80) + field(recording, 80) + field(date, 8) + field(time, 8) +
         field(std::to_string(256 * (signals + 1)), 8) + field("EDF+C", 44) + field(std::to_string(records), 8) +
         field(fixed(kRecordS, 0), 8) + field(std::to_string(signals), 4);
}

/// The 256 bytes per signal that follow the main header: each field for every signal in
/// turn, as the spec lays them out.
std::string signal_headers(const std::vector<SignalHeader>& signals) {
  std::string out;
  const auto each = [&](std::size_t width, auto&& value) {
    for (const auto& s : signals) out += field(value(s), width);
  };
  each(16, [](const SignalHeader& s) { return s.label; });
  each(80, [](const SignalHeader&) { return std::string(); });  // transducer type
  each(8, [](const SignalHeader& s) { return s.dimension; });
  each(8, [](const SignalHeader& s) { return s.physical_min; });
  each(8, [](const SignalHeader& s) { return s.physical_max; });
  each(8, [](const SignalHeader&) { return std::to_string(kDigitalMin); });
  each(8, [](const SignalHeader&) { return std::to_string(kDigitalMax); });
  each(80, [](const SignalHeader&) { return std::string(); });  // prefiltering: none
  each(8, [](const SignalHeader& s) { return std::to_string(s.samples_per_record); });
  each(32, [](const SignalHeader&) { return std::string(); });  // reserved
  return out;
}

/// The physical maximum of a lead whose largest |value| is `peak_mv`, as its header text:
/// rounded up at the last decimal that fits the 8-character field with a minus sign (the
/// tightest range, the finest step), at least one unit of that decimal (never zero-width).
std::string physical_limit(double peak_mv, const std::string& lead) {
  for (int decimals = 5; decimals >= 0; --decimals) {
    const double unit = std::pow(10.0, -decimals);
    const double limit = std::max(std::ceil(peak_mv / unit), 1.0) * unit;
    if (fixed(-limit, decimals).size() <= kFieldWidth) return fixed(limit, decimals);
  }
  throw Error(ExitCode::kInternal, "ECG lead " + lead + " reaches " + fixed(peak_mv, 0) +
                                       " mV, more than an EDF header field can hold (and than any heart makes)");
}

/// A TAL onset or duration [s] for sample `sample` at `rate` samples per second: exact for
/// whole seconds, else 9 decimals (a reader rounds it to the sample), trailing zeros cut.
std::string tal_seconds(std::size_t sample, int rate) {
  const std::size_t whole = sample / static_cast<std::size_t>(rate);
  const std::size_t rest = sample % static_cast<std::size_t>(rate);
  if (rest == 0) return std::to_string(whole);
  std::string text = fixed(static_cast<double>(rest) / rate, 9);
  text.erase(text.find_last_not_of('0') + 1);
  return std::to_string(whole) + text.substr(1);  // text is "0.xxx": keep ".xxx"
}

/// Each record's annotation bytes: its time-keeping TAL, and in the last record, when the
/// ECG does not fill it, the TAL that marks the padding.
std::vector<std::string> annotation_lists(std::size_t samples, int per_record, std::size_t records) {
  std::vector<std::string> lists(records);
  for (std::size_t k = 0; k < records; ++k) {
    lists[k] = "+" + tal_seconds(k * static_cast<std::size_t>(per_record), per_record) + kTalTextEnd + kTalTextEnd;
    lists[k] += '\0';
  }
  const std::size_t padded = records * static_cast<std::size_t>(per_record) - samples;
  if (padded > 0) {
    lists.back() += "+" + tal_seconds(samples, per_record) + kTalOnsetEnd + tal_seconds(padded, per_record) +
                    kTalTextEnd + std::string(kPaddingText) + kTalTextEnd;
    lists.back() += '\0';
  }
  return lists;
}

/// A little-endian 16-bit sample.
void put_sample(std::string& out, int value) {
  const auto bits = static_cast<std::uint16_t>(static_cast<std::int16_t>(value));
  out += static_cast<char>(bits & 0xff);
  out += static_cast<char>(bits >> 8);
}

/// `mv` as a digital value of the signal whose physical range is [-limit, limit].
int digital(double mv, double limit) {
  const double step = 2 * limit / (kDigitalMax - kDigitalMin);
  const double d = std::round((mv + limit) / step) + kDigitalMin;
  return static_cast<int>(std::clamp(d, double(kDigitalMin), double(kDigitalMax)));
}

/// The ECG signals' headers, each lead's range taken from its own samples.
std::vector<SignalHeader> lead_headers(const Ecg& ecg, int per_record) {
  std::vector<SignalHeader> out;
  for (std::size_t l = 0; l < ecg.leads.size(); ++l) {
    const std::string label = std::string(kLeadPrefix) + ecg.leads[l];
    if (label.size() > 16 || subfield(ecg.leads[l], 16) != ecg.leads[l]) {
      throw Error(ExitCode::kInternal, "ECG lead name '" + ecg.leads[l] +
                                           "' does not fit EDF's 16-character label as '" + label + "'");
    }
    double peak = 0;
    for (const double v : ecg.mv[l]) peak = std::max(peak, std::abs(v));
    const std::string limit = physical_limit(peak, ecg.leads[l]);
    out.push_back({label, "mV", "-" + limit, limit, per_record});
  }
  return out;
}

/// Data record `k`: each lead's samples (the last one repeated past the ECG's end), then
/// the annotation signal's bytes, zero-filled.
std::string data_record(const Ecg& ecg, const std::vector<double>& limits, std::size_t k, int per_record,
                        const std::string& annotations, int annotation_samples) {
  std::string out;
  for (std::size_t l = 0; l < ecg.mv.size(); ++l) {
    for (int i = 0; i < per_record; ++i) {
      const std::size_t at = std::min(k * static_cast<std::size_t>(per_record) + static_cast<std::size_t>(i),
                                      ecg.samples() - 1);
      put_sample(out, digital(ecg.mv[l][at], limits[l]));
    }
  }
  std::string tal = annotations;
  tal.resize(2 * static_cast<std::size_t>(annotation_samples), '\0');
  return out + tal;
}

}  // namespace

void write_ecg_edf(const Ecg& ecg, const fs::path& file, const EdfInfo& info) {
  check_consistent(ecg);
  if (ecg.leads.empty() || ecg.samples() == 0) {
    throw Error(ExitCode::kInternal, "cannot write '" + file.string() + "': the ECG has no samples");
  }
  const int per_record = samples_per_record(ecg.rate_hz);
  check_start(info.start);
  const std::size_t records = (ecg.samples() + per_record - 1) / per_record;
  const auto annotations = annotation_lists(ecg.samples(), per_record, records);
  std::size_t longest = 0;
  for (const auto& a : annotations) longest = std::max(longest, a.size());
  const int annotation_samples = static_cast<int>((longest + 1) / 2);

  auto signals = lead_headers(ecg, per_record);
  std::vector<double> limits;
  // Scale by the header's texts, not the unrounded peaks, so that any reader decodes
  // exactly what was encoded.
  for (const auto& s : signals) limits.push_back(std::strtod(s.physical_max.c_str(), nullptr));
  // The annotation signal's ranges are unused, but readers expect them to differ.
  signals.push_back({std::string(kAnnotationLabel), "", "-1", "1", annotation_samples});

  write_atomically(file, [&](std::ostream& out) {
    out << main_header(info, signals.size(), records) << signal_headers(signals);
    for (std::size_t k = 0; k < records; ++k) {
      out << data_record(ecg, limits, k, per_record, annotations[k], annotation_samples);
    }
  });
}

namespace {

// ---------------------------------------------------------------------------------------
// EDF+ reading

/// The header as read_ecg_edf needs it.
struct ReadHeader {
  std::size_t header_bytes = 0;
  std::size_t records = 0;
  double record_s = 0;
  std::vector<std::string> labels;
  std::vector<double> physical_min, physical_max, digital_min, digital_max;
  std::vector<std::size_t> samples_per_record;
  std::size_t record_bytes = 0;
};

/// Reads EDF bytes and reports what is wrong with them, naming the file.
class EdfBytes {
 public:
  EdfBytes(fs::path file, std::string bytes) : file_(std::move(file)), bytes_(std::move(bytes)) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw Error(ExitCode::kDataError, file_.string() + ": " + what);
  }

  /// The field of `width` bytes at `at`, trailing spaces cut.
  std::string text(std::size_t at, std::size_t width, const std::string& name) const {
    if (at + width > bytes_.size()) fail("ends inside the header (at its " + name + ")");
    std::string out = bytes_.substr(at, width);
    out.erase(out.find_last_not_of(' ') + 1);
    return out;
  }

  /// The numeric field of `width` bytes at `at`.
  double number(std::size_t at, std::size_t width, const std::string& name) const {
    const std::string t = text(at, width, name);
    char* end = nullptr;
    const double value = std::strtod(t.c_str(), &end);
    if (t.empty() || *end != '\0' || !std::isfinite(value)) fail("its " + name + " '" + t + "' is not a number");
    return value;
  }

  /// The whole, non-negative numeric field of `width` bytes at `at`.
  std::size_t count(std::size_t at, std::size_t width, const std::string& name) const {
    const double value = number(at, width, name);
    // An 8-digit field holds at most 99999999; more is a malformed one ("1e99").
    if (value < 0 || value != std::floor(value) || value > 99999999) {
      fail("its " + name + " is not a whole number from 0 to 99999999: " + text(at, width, name));
    }
    return static_cast<std::size_t>(value);
  }

  /// The 16-bit little-endian sample at byte `at`.
  int sample(std::size_t at) const {
    const auto lo = static_cast<unsigned char>(bytes_[at]), hi = static_cast<unsigned char>(bytes_[at + 1]);
    return static_cast<std::int16_t>(static_cast<std::uint16_t>(lo | (hi << 8)));
  }

  std::size_t size() const { return bytes_.size(); }
  std::string_view view(std::size_t at, std::size_t n) const { return std::string_view(bytes_).substr(at, n); }

 private:
  fs::path file_;
  std::string bytes_;
};

/// The signal fields of `h`, laid out after the main header.
void read_signal_headers(const EdfBytes& in, std::size_t signals, ReadHeader& h) {
  std::size_t at = 256;
  const auto column = [&](std::size_t width, const std::string& name, auto&& store) {
    for (std::size_t s = 0; s < signals; ++s) store(at + s * width, width, name + " of signal " + std::to_string(s + 1));
    at += signals * width;
  };
  const auto numbers = [&](std::vector<double>& out) {
    return [&](std::size_t a, std::size_t w, const std::string& n) { out.push_back(in.number(a, w, n)); };
  };
  column(16, "label", [&](std::size_t a, std::size_t w, const std::string& n) { h.labels.push_back(in.text(a, w, n)); });
  at += signals * (80 + 8);  // transducer, physical dimension
  column(8, "physical minimum", numbers(h.physical_min));
  column(8, "physical maximum", numbers(h.physical_max));
  column(8, "digital minimum", numbers(h.digital_min));
  column(8, "digital maximum", numbers(h.digital_max));
  at += signals * 80;  // prefiltering
  column(8, "samples per record", [&](std::size_t a, std::size_t w, const std::string& n) {
    h.samples_per_record.push_back(in.count(a, w, n));
  });
  for (std::size_t s = 0; s < signals; ++s) {
    if (h.digital_max[s] <= h.digital_min[s] || h.physical_max[s] == h.physical_min[s]) {
      in.fail("signal " + std::to_string(s + 1) + " '" + h.labels[s] + "' has an empty digital or physical range");
    }
    h.record_bytes += 2 * h.samples_per_record[s];
  }
}

/// The main header and the signal headers, checked against the file's size.
ReadHeader read_header(const EdfBytes& in) {
  if (in.text(0, 8, "version") != "0") in.fail("is not EDF (its version field is not '0')");
  if (in.text(192, 44, "reserved field").rfind("EDF+C", 0) != 0) {
    in.fail("is not continuous EDF+ (its reserved field does not start with 'EDF+C')");
  }
  ReadHeader h;
  const std::size_t signals = in.count(252, 4, "number of signals");
  h.header_bytes = in.count(184, 8, "header size");
  if (signals == 0 || h.header_bytes != 256 * (signals + 1)) {
    in.fail("its header size " + std::to_string(h.header_bytes) + " does not match its " + std::to_string(signals) +
            " signals (256 bytes each, plus 256)");
  }
  if (in.size() < h.header_bytes) {
    in.fail("ends inside the header (" + std::to_string(in.size()) + " of its " + std::to_string(h.header_bytes) +
            " bytes)");
  }
  h.records = in.count(236, 8, "number of data records");
  h.record_s = in.number(244, 8, "data record duration");
  if (!(h.record_s > 0)) in.fail("its data record duration is not positive");
  read_signal_headers(in, signals, h);
  if (h.record_bytes == 0) in.fail("its signals hold no samples");
  // Compared by division: records x record bytes can overflow for a hostile header.
  const std::size_t data_bytes = in.size() - h.header_bytes;
  if (data_bytes % h.record_bytes != 0 || data_bytes / h.record_bytes != h.records) {
    in.fail("is " + std::to_string(in.size()) + " bytes, but its header announces " + std::to_string(h.records) +
            " data records of " + std::to_string(h.record_bytes) + " bytes after its " +
            std::to_string(h.header_bytes) + " header bytes");
  }
  return h;
}

/// One time-stamped annotation list: its onset [s] and its texts (a time-keeping TAL has
/// one, empty).
struct Tal {
  double onset_s = 0;
  std::vector<std::string> texts;
};

/// The TALs in one record's annotation bytes: "+onset[\x15duration]\x14text\x14...\x14\0"
/// each, until the unused bytes (zeros).
std::vector<Tal> read_tals(const EdfBytes& in, std::string_view bytes, const std::string& where) {
  std::vector<Tal> out;
  for (std::size_t at = 0; at < bytes.size() && bytes[at] != '\0';) {
    const std::size_t end = bytes.find('\0', at);
    const std::string_view tal = bytes.substr(at, end == std::string_view::npos ? std::string_view::npos : end - at);
    const std::size_t texts_at = tal.find(kTalTextEnd);
    if (end == std::string_view::npos || texts_at == std::string_view::npos || tal.size() < texts_at + 2 ||
        tal.back() != kTalTextEnd) {
      in.fail(where + " holds a malformed annotation list (no closing \\x14 and \\0)");
    }
    const std::string onset(tal.substr(0, std::min(texts_at, tal.find(kTalOnsetEnd))));
    char* onset_end = nullptr;
    Tal parsed;
    parsed.onset_s = std::strtod(onset.c_str(), &onset_end);
    if (onset.size() < 2 || (onset[0] != '+' && onset[0] != '-') || *onset_end != '\0') {
      in.fail(where + " holds a malformed annotation onset '" + onset + "'");
    }
    // The texts sit between the onset's \x14 and the last one, \x14-separated.
    const std::string_view texts = tal.substr(texts_at + 1, tal.size() - texts_at - 2);
    for (std::size_t t = 0;; t = texts.find(kTalTextEnd, t) + 1) {
      parsed.texts.emplace_back(texts.substr(t, texts.find(kTalTextEnd, t) - t));
      if (texts.find(kTalTextEnd, t) == std::string_view::npos) break;
    }
    out.push_back(std::move(parsed));
    at = end + 1;
  }
  return out;
}

/// How many of the `all` samples are the ECG's: up to where a "BAD_padding" annotation
/// starts, else all. Checks that each record starts with its time-keeping TAL, at the time a
/// continuous recording puts it.
std::size_t unpadded_samples(const EdfBytes& in, const ReadHeader& h, std::size_t signal, double rate_hz,
                             std::size_t all) {
  std::size_t offset = h.header_bytes;
  for (std::size_t s = 0; s < signal; ++s) offset += 2 * h.samples_per_record[s];
  std::size_t samples = all;
  for (std::size_t k = 0; k < h.records; ++k) {
    const std::string where = "data record " + std::to_string(k + 1);
    const auto tals = read_tals(in, in.view(offset + k * h.record_bytes, 2 * h.samples_per_record[signal]), where);
    if (tals.empty() || tals[0].texts != std::vector<std::string>{""}) {
      in.fail(where + " does not start with a time-keeping annotation ('+<onset>\\x14\\x14\\0')");
    }
    const double expected_s = static_cast<double>(k) * h.record_s;
    if (std::abs(tals[0].onset_s - expected_s) > 0.5 / rate_hz) {
      in.fail(where + " starts at " + fixed(tals[0].onset_s, 6) + " s, not at " + fixed(expected_s, 6) +
              " s where a continuous (EDF+C) recording puts it");
    }
    for (const Tal& tal : tals) {
      if (std::find(tal.texts.begin(), tal.texts.end(), kPaddingText) == tal.texts.end()) continue;
      samples = static_cast<std::size_t>(std::llround(std::max(0.0, tal.onset_s) * rate_hz));
    }
  }
  return std::min(samples, all);
}

}  // namespace

Ecg read_ecg_edf(const fs::path& file) {
  if (const auto why = unreadable_file_reason(file)) {
    throw Error(ExitCode::kNoInput, "cannot read ECG '" + file.string() + "': " + *why);
  }
  std::ifstream stream(file, std::ios::binary);
  const EdfBytes in(file, {std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()});
  const ReadHeader h = read_header(in);
  const auto annotation = std::find(h.labels.begin(), h.labels.end(), kAnnotationLabel);
  if (annotation == h.labels.end()) in.fail("has no 'EDF Annotations' signal, which EDF+ requires");
  const auto annotation_signal = static_cast<std::size_t>(annotation - h.labels.begin());

  Ecg ecg;
  std::vector<std::size_t> lead_signals;
  for (std::size_t s = 0; s < h.labels.size(); ++s) {
    if (s == annotation_signal) continue;
    const std::string& label = h.labels[s];
    ecg.leads.push_back(label.rfind(kLeadPrefix, 0) == 0 ? label.substr(kLeadPrefix.size()) : label);
    lead_signals.push_back(s);
    if (h.samples_per_record[s] != h.samples_per_record[lead_signals[0]]) {
      in.fail("signal '" + label + "' has " + std::to_string(h.samples_per_record[s]) + " samples per record, '" +
              h.labels[lead_signals[0]] + "' " + std::to_string(h.samples_per_record[lead_signals[0]]) +
              ": an ECG's leads share one rate");
    }
  }
  if (lead_signals.empty()) in.fail("holds no signals besides its annotations");
  const std::size_t per_record = h.samples_per_record[lead_signals[0]];
  ecg.rate_hz = static_cast<double>(per_record) / h.record_s;
  const std::size_t samples = unpadded_samples(in, h, annotation_signal, ecg.rate_hz, h.records * per_record);

  std::vector<std::size_t> offsets(h.labels.size(), 0);  // Each signal's bytes within a record.
  for (std::size_t s = 1; s < offsets.size(); ++s) offsets[s] = offsets[s - 1] + 2 * h.samples_per_record[s - 1];
  for (const std::size_t s : lead_signals) {
    const double gain = (h.physical_max[s] - h.physical_min[s]) / (h.digital_max[s] - h.digital_min[s]);
    std::vector<double> mv(samples);
    for (std::size_t i = 0; i < samples; ++i) {
      const std::size_t at = h.header_bytes + (i / per_record) * h.record_bytes + offsets[s] + 2 * (i % per_record);
      mv[i] = h.physical_min[s] + (in.sample(at) - h.digital_min[s]) * gain;
    }
    ecg.mv.push_back(std::move(mv));
  }
  return ecg;
}

}  // namespace systole::electro

#pragma once
// The ECG's files: CSV for spreadsheets and plotting scripts, EDF+ for the viewers and
// toolkits of clinical physiology (EDFbrowser, MNE-Python, Luna); and the EDF+ reader that
// checks what we write reads back.
//
// EDF+ (Kemp & Olivan 2003, https://www.edfplus.info/specs/edfplus.html) as written here:
// - continuous ("EDF+C"), 1 s data records, so the sampling rate must be a whole number of
//   Hz (a record holds rate_hz samples per signal; other rates are refused);
// - one signal per lead, labelled "ECG <lead>", in mV, digital range -32768..32767, physical
//   range symmetric, +-(the lead's largest |value|, rounded up at the last digit the 8-character
//   field can show), never zero-width: the quantisation step is that range / 65535;
// - the mandatory "EDF Annotations" signal: each record starts with its time-keeping TAL
//   ("+<k>\x14\x14\0", record k starting k s after the header's start time);
// - a last record the ECG does not fill is padded with copies of each lead's last sample (no
//   step for a viewer's filters to ring on), and marked by the annotation "BAD_padding"
//   over the padded span: MNE and others read the padding as samples, and MNE leaves spans
//   whose annotation starts with "BAD" out of epochs; read_ecg_edf drops it.
// The header's start date and time mark the first sample (EdfInfo::start); Ecg::start_s,
// a time on the clip's clock, has no place in EDF and is not written.

#include <filesystem>
#include <string>

#include "electro/ecg.h"

namespace systole::electro {

/// A wall-clock date and time, whole seconds (EDF's header has no finer field).
struct EdfDateTime {
  int year = 2000;  ///< 1985..2084: the span EDF's two-digit header year can name.
  int month = 1;    ///< 1..12
  int day = 1;      ///< 1..31, valid for the month
  int hour = 0;     ///< 0..23
  int minute = 0;   ///< 0..59
  int second = 0;   ///< 0..59
};

/// What an EDF+ header says besides the signals. The defaults are fixed so that the same
/// ECG gives the same bytes on every run.
struct EdfInfo {
  /// When the first sample was taken. A simulation has no wall clock: callers pass a fixed
  /// date, or today's when a user asks for it.
  EdfDateTime start;
  /// The patient's name subfield ("X" = unknown), e.g. the scene's name. Spaces become '_'
  /// and bytes outside printable ASCII become '_' (EDF+ headers are ASCII, subfields are
  /// space-separated); cut to fit the 80-character field.
  std::string patient = "X";
  /// The recording's administration-code subfield ("X" = unknown), e.g. the scene file's
  /// name; the same rules as `patient`.
  std::string recording = "X";
};

/// Writes `ecg` as CSV: the header `time_s,<lead>,...`, then one row per sample with its
/// time on the clip's clock (start_s + i / rate_hz, 6 decimals: [s]) and each lead (4
/// decimals: [mV], finer than 1 uV). Whole or not at all (common/atomic_output.h). Throws
/// Error(kInternal) for an ECG whose leads disagree in length or hold a non-finite value,
/// and the errors of write_atomically.
void write_ecg_csv(const Ecg& ecg, const std::filesystem::path& file);

/// Writes `ecg` as EDF+ (see the top of this file). Whole or not at all. Throws
/// Error(kDataError) for a rate that is not a whole number of Hz or an `info` EDF cannot
/// hold, Error(kInternal) for an empty or inconsistent ECG or one whose amplitude no 8-digit
/// field can hold, and the errors of write_atomically.
void write_ecg_edf(const Ecg& ecg, const std::filesystem::path& file, const EdfInfo& info = {});

/// Reads an EDF+C file that write_ecg_edf wrote: its "ECG <lead>" signals (the prefix
/// removed) in mV, at the rate its records give, the padding dropped; start_s is 0. Throws
/// Error(kNoInput) when the file cannot be read and Error(kDataError), naming the file and
/// what is wrong, when it is not such a file.
Ecg read_ecg_edf(const std::filesystem::path& file);

}  // namespace systole::electro

#include "batch/batch.h"

#include <glob.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <thread>

#include "batch/manifest.h"
#include "encode/video_writer.h"
#include "world/bake.h"
#include "clip/frame_list.h"
#include "clip/video_format.h"
#include "common/atomic_output.h"
#include "common/error.h"
#include "common/interrupt.h"
#include "common/json.h"
#include "scene/content_hash.h"
#include "scene/load.h"

namespace systole::batch {
namespace fs = std::filesystem;

namespace {

std::string trim(std::string_view s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string_view::npos) return {};
  return std::string(s.substr(b, s.find_last_not_of(" \t") - b + 1));
}

bool is_scene_file(const fs::path& p) { return p.extension() == ".yaml" || p.extension() == ".yml"; }

/// Files, folders (their scenes, sorted) and glob patterns (matches, sorted), in order.
std::vector<fs::path> expand_scene_inputs(const std::vector<std::string>& inputs) {
  std::vector<fs::path> scenes;
  for (const auto& in : inputs) {
    std::error_code ec;
    if (in.find_first_of("*?[") != std::string::npos && !fs::exists(in, ec)) {
      glob_t matches{};
      const int rc = ::glob(in.c_str(), 0, nullptr, &matches);
      const std::size_t before = scenes.size();
      for (std::size_t i = 0; rc == 0 && i < matches.gl_pathc; ++i) scenes.emplace_back(matches.gl_pathv[i]);
      ::globfree(&matches);
      if (scenes.size() == before) throw Error(ExitCode::kNoInput, "no scene matches '" + in + "'");
    } else if (fs::is_directory(in, ec)) {
      std::vector<fs::path> found;
      for (const auto& entry : fs::directory_iterator(in)) {
        if (!is_scene_file(entry.path())) continue;
        // A scene entry whose kind cannot be read (a symlink loop, a dangling link) is still
        // a job: it fails alone, with its own exit code, and the others render.
        std::error_code unreadable;
        if (entry.is_regular_file(unreadable) || unreadable) found.push_back(entry.path());
      }
      if (found.empty()) throw Error(ExitCode::kNoInput, "folder '" + in + "' holds no scene (*.yaml, *.yml)");
      std::sort(found.begin(), found.end());
      scenes.insert(scenes.end(), found.begin(), found.end());
    } else {
      scenes.emplace_back(in);  // A missing file fails its own job, with the others rendered.
    }
  }
  return scenes;
}

struct Define {
  std::string key;
  std::vector<std::string> values;
};

std::vector<std::string> split_path(const std::string& key) {
  std::vector<std::string> segments;
  std::stringstream in(key);
  for (std::string s; std::getline(in, s, '.');) segments.push_back(s);
  return segments;
}

/// For each swept key, the shortest suffix of its path that no other swept key ends with.
std::map<std::string, std::string> name_labels(const std::vector<Define>& defines) {
  std::vector<std::string> swept;
  for (const auto& d : defines) {
    if (d.values.size() > 1) swept.push_back(d.key);
  }
  std::map<std::string, std::string> labels;
  for (const auto& key : swept) {
    const auto mine = split_path(key);
    for (std::size_t n = 1; n <= mine.size(); ++n) {
      auto suffix = [n](const std::vector<std::string>& p) {
        std::string s;
        for (std::size_t i = p.size() >= n ? p.size() - n : 0; i < p.size(); ++i) s += (s.empty() ? "" : ".") + p[i];
        return s;
      };
      const std::string label = suffix(mine);
      const bool shared = std::any_of(swept.begin(), swept.end(), [&](const std::string& other) {
        return other != key && suffix(split_path(other)) == label;
      });
      if (!shared || n == mine.size()) {
        labels[key] = label;
        break;
      }
    }
  }
  return labels;
}

std::string name_part(const std::string& value) {
  std::string out;
  for (const char c : value) {
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '+' || c == '-') {
      out += c;
    } else if (std::strchr(" \t'\"[](){}", c) == nullptr && !out.empty() && out.back() != '_') {
      out += '_';
    }
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  return out;
}

const char* status_name(JobResult::Status s) {
  switch (s) {
    case JobResult::Status::kDone: return "done";
    case JobResult::Status::kSkipped: return "skipped";
    case JobResult::Status::kFailed: return "failed";
  }
  return "?";
}

/// A non-negative integer from an environment variable, or an error naming it.
int env_index(const char* name, const char* text) {
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(text, &end, 10);
  if (*text == '\0' || *end != '\0' || errno != 0 || v < 0 || v > 1'000'000'000) {
    throw Error(ExitCode::kUsage, std::string(name) + "='" + text + "' is not a non-negative whole number");
  }
  return static_cast<int>(v);
}

}  // namespace

std::vector<std::string> split_sweep_values(std::string_view value) {
  std::vector<std::string> values;
  int depth = 0;
  char quote = 0;
  std::size_t start = 0;
  for (std::size_t i = 0; i < value.size(); ++i) {
    const char c = value[i];
    if (quote) {
      if (c == quote) quote = 0;
    } else if (c == '\'' || c == '"') {
      quote = c;
    } else if (c == '[' || c == '{' || c == '(') {
      ++depth;
    } else if ((c == ']' || c == '}' || c == ')') && depth > 0) {
      --depth;
    } else if (c == ',' && depth == 0) {
      values.push_back(trim(value.substr(start, i - start)));
      start = i + 1;
    }
  }
  values.push_back(trim(value.substr(start)));
  return values;
}

std::vector<Job> expand_jobs(const std::vector<std::string>& scenes, const std::vector<std::string>& defines) {
  std::vector<Define> parsed;
  for (const auto& d : defines) {
    const auto eq = d.find('=');
    if (eq == std::string::npos) throw Error(ExitCode::kUsage, "-D " + d + ": expected key.path=value");
    parsed.push_back({trim(d.substr(0, eq)), split_sweep_values(std::string_view(d).substr(eq + 1))});
  }
  const auto labels = name_labels(parsed);

  std::vector<Job> jobs;
  std::map<std::string, fs::path> seen;
  for (const auto& scene : expand_scene_inputs(scenes)) {
    // The cartesian product as an odometer over the value lists, the last -D turning fastest.
    std::vector<std::size_t> pick(parsed.size(), 0);
    for (bool more = true; more;) {
      Job job{scene.stem().string(), scene, {}, !labels.empty()};
      for (std::size_t i = 0; i < parsed.size(); ++i) {
        const std::string& value = parsed[i].values[pick[i]];
        job.overrides.push_back(parsed[i].key + "=" + value);
        if (parsed[i].values.size() > 1) job.name += "_" + name_part(labels.at(parsed[i].key)) + "-" + name_part(value);
      }
      if (auto [it, fresh] = seen.emplace(job.name, scene); !fresh) {
        throw Error(ExitCode::kUsage, "two jobs would be named '" + job.name + "' (" + it->second.string() + " and " +
                                          scene.string() + "): rename a scene or make the sweep values differ");
      }
      jobs.push_back(std::move(job));
      more = false;
      for (std::size_t i = parsed.size(); i-- > 0;) {
        if (++pick[i] < parsed[i].values.size()) {
          more = true;
          break;
        }
        pick[i] = 0;
      }
    }
  }
  return jobs;
}

Shard parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  int index = -1, count = 0;
  try {
    std::size_t used = 0;
    if (slash != std::string::npos) {
      index = std::stoi(text.substr(0, slash), &used);
      if (used != slash) index = -1;
      count = std::stoi(text.substr(slash + 1), &used);
      if (used != text.size() - slash - 1) count = 0;
    }
  } catch (const std::exception&) {
    index = -1;
  }
  if (index < 0 || count < 1 || index >= count) {
    throw Error(ExitCode::kUsage, "--shard " + text + ": expected i/N with 0 <= i < N (e.g. 0/4 ... 3/4)");
  }
  return {index, count, "--shard"};
}

Shard shard_from_environment(const Environment& getenv) {
  struct Pair {
    const char* source;
    const char* index;
    const char* count;
  };
  static constexpr Pair kPairs[] = {
      {"Slurm", "SLURM_ARRAY_TASK_ID", "SLURM_ARRAY_TASK_COUNT"},
      {"Kubernetes", "JOB_COMPLETION_INDEX", "SYSTOLE_SHARD_COUNT"},
      {"AWS Batch", "AWS_BATCH_JOB_ARRAY_INDEX", "AWS_BATCH_JOB_ARRAY_SIZE"},
  };
  for (const auto& p : kPairs) {
    const char* index = getenv(p.index);
    const char* count = getenv(p.count);
    if (!index && !count) continue;
    if (!index || !count) {
      throw Error(ExitCode::kUsage, std::string(p.source) + " array: " + (index ? p.index : p.count) + " is set but " +
                                        (index ? p.count : p.index) + " is not; set both, or pass --shard i/N");
    }
    Shard shard{env_index(p.index, index), env_index(p.count, count), p.source};
    // Slurm numbers tasks as the user wrote --array (1-8 as well as 0-7).
    if (const char* min = std::string(p.source) == "Slurm" ? getenv("SLURM_ARRAY_TASK_MIN") : nullptr) {
      shard.index -= env_index("SLURM_ARRAY_TASK_MIN", min);
    }
    if (shard.count < 1 || shard.index < 0 || shard.index >= shard.count) {
      throw Error(ExitCode::kUsage, std::string(p.source) + " array: task " + index + " of " + count +
                                        " is not an index in 0.." + std::to_string(shard.count - 1) +
                                        " (use a contiguous array, e.g. --array=0-" +
                                        std::to_string(std::max(0, shard.count - 1)) + ")");
    }
    return shard;
  }
  return {};
}

std::vector<Job> select_shard(const std::vector<Job>& jobs, const Shard& shard) {
  std::vector<Job> mine;
  for (std::size_t k = 0; k < jobs.size(); ++k) {
    if (static_cast<int>(k % shard.count) == shard.index) mine.push_back(jobs[k]);
  }
  return mine;
}

clip::RenderRequest plan_request(const Job& job, const scene::Scene& scene, const BatchOptions& options) {
  clip::RenderRequest request;
  const fs::path& o = options.output;
  std::error_code ec;
  // "-o out/d.mp4/" names a folder by its slash and a video by its name: say so rather than
  // make a folder called d.mp4.
  if (!o.empty() && !o.has_filename() && encode::video_format_of(o.parent_path()) && !fs::is_directory(o, ec)) {
    throw Error(ExitCode::kUsage, "-o " + o.string() + ": the '/' at its end names a folder, but '" +
                                      o.parent_path().filename().string() +
                                      "' is a video's name; drop the '/' to write that video, or name the folder without "
                                      "a video's extension");
  }
  const bool output_is_folder = !o.empty() && (options.several || fs::is_directory(o, ec) || !o.has_filename());
  const std::string extension = clip::default_video_path(scene).extension().string();
  const fs::path named_video = output_is_folder ? o / (job.name + (extension.empty() ? ".mp4" : extension)) : o;
  if (!options.frames.empty()) {
    // A selection is for stills: a video is written only when asked for with -o (so a
    // partial clip never replaces the default video), and it must be a range.
    request.frames = clip::parse_frame_list(options.frames, scene.output.frame_count());
    if (options.png_dir.empty() && (o.empty() || options.no_video)) {
      throw Error(ExitCode::kUsage,
                  "--frames renders PNG frames: add --png DIR (and -o OUT.mp4 for a video of a consecutive range)");
    }
    if (!options.no_video && !o.empty()) request.video = named_video;
  } else if (!options.no_video) {
    if (!o.empty()) {
      request.video = named_video;
    } else {
      const fs::path scene_default = clip::default_video_path(scene);
      request.video = job.swept ? scene_default.parent_path() / (job.name + (extension.empty() ? ".mp4" : extension)) : scene_default;
    }
  }
  // Folders that name a batch's outputs are ours to create; a file named with -o must be in
  // an existing folder, so a typo in it is reported rather than silently created.
  if (!request.video.empty() && (o.empty() || output_is_folder) && request.video.has_parent_path()) {
    fs::create_directories(request.video.parent_path());
  }
  if (!options.png_dir.empty()) request.png_dir = options.several ? options.png_dir / job.name : options.png_dir;
  if (!options.wav.empty()) request.wav = options.several ? options.wav / (job.name + ".wav") : options.wav;
  request.from_bake = options.from_bake;
  request.limits = options.limits;
  request.progress = options.progress;
  request.job = job.name;
  return request;
}

JobResult run_job(const Job& job, const BatchOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  JobResult result;
  result.job = job.name;
  try {
    const auto scene = scene::load(job.scene, job.overrides);
    const clip::RenderRequest request = plan_request(job, scene, options);
    result.output = (request.video.empty() ? request.png_dir : request.video).string();
    JobIdentity identity{job.scene.string(), scene::scene_content_hash(scene), job.overrides, options.frames, 0};
    if (!options.from_bake.empty()) identity.bake_checksum = world::BakeReader(options.from_bake).checksum();
    const std::string who = options.several ? job.name + ": " : "";
    // Leftovers of a run that died (SIGKILL, a lost node) go even when this job is skipped.
    if (!request.video.empty()) sweep_stale_outputs(request.video.has_parent_path() ? request.video.parent_path() : ".");
    if (!request.video.empty() && request.png_dir.empty() && request.wav.empty() && !options.force && up_to_date(request.video, identity)) {
      std::cerr << who << "up to date, skipped: " << request.video.string() << " (--force renders it again)\n";
      result.status = JobResult::Status::kSkipped;
    } else {
      const auto times = clip::render_clip(scene, request);
      if (!request.video.empty()) write_manifest(request.video, identity);
      if (!request.video.empty()) std::cerr << who << "wrote " << request.video.string() << "\n";
      if (!request.png_dir.empty()) {
        std::cerr << who << "wrote " << times.frames << " PNG frames to " << request.png_dir.string() << "\n";
      }
      std::cerr << who << clip::describe(times) << "\n";
      result.status = JobResult::Status::kDone;
    }
  } catch (const Error& e) {
    result.error = e.what();
    result.exit_code = static_cast<int>(e.code());
  } catch (const std::bad_alloc&) {
    result.error = out_of_memory_error().what();
    result.exit_code = static_cast<int>(ExitCode::kOutOfMemory);
  } catch (const std::exception& e) {
    result.error = std::string("internal error: ") + e.what();
    result.exit_code = static_cast<int>(ExitCode::kInternal);
  }
  result.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

namespace {

// A child reports its result through a pipe: fixed fields, then two length-prefixed
// strings, kept under PIPE_BUF so the write is whole and never blocks the exiting child.
void send_result(int fd, const JobResult& r) {
  std::string msg;
  auto put = [&](const void* p, std::size_t n) { msg.append(static_cast<const char*>(p), n); };
  const int status = static_cast<int>(r.status);
  put(&status, sizeof status);
  put(&r.exit_code, sizeof r.exit_code);
  put(&r.wall_s, sizeof r.wall_s);
  for (const std::string* s : {&r.output, &r.error}) {
    const std::uint32_t n = static_cast<std::uint32_t>(std::min<std::size_t>(s->size(), 1800));
    put(&n, sizeof n);
    put(s->data(), n);
  }
  [[maybe_unused]] auto written = ::write(fd, msg.data(), msg.size());
}

bool receive_result(int fd, JobResult& r) {
  char buf[4096];
  std::string msg;
  for (ssize_t n; (n = ::read(fd, buf, sizeof buf)) > 0;) msg.append(buf, static_cast<std::size_t>(n));
  std::size_t at = 0;
  auto get = [&](void* p, std::size_t n) {
    if (at + n > msg.size()) return false;
    std::memcpy(p, msg.data() + at, n);
    at += n;
    return true;
  };
  int status = 0;
  if (!get(&status, sizeof status) || !get(&r.exit_code, sizeof r.exit_code) || !get(&r.wall_s, sizeof r.wall_s)) {
    return false;
  }
  r.status = static_cast<JobResult::Status>(status);
  for (std::string* s : {&r.output, &r.error}) {
    std::uint32_t n = 0;
    if (!get(&n, sizeof n) || at + n > msg.size()) return false;
    s->assign(msg.data() + at, n);
    at += n;
  }
  return true;
}

[[noreturn]] void run_child(const Job& job, BatchOptions options, int fd) {
  // Die with the batch: a killed parent must not leave renders running (their SIGTERM
  // handler removes their temporaries).
  ::prctl(PR_SET_PDEATHSIG, SIGTERM);
  // Terminal progress lines of several jobs would overwrite each other.
  if (options.parallel > 1 && options.progress == clip::ProgressStyle::kTerminal) options.progress = clip::ProgressStyle::kNone;
  const JobResult r = run_job(job, options);
  if (r.status == JobResult::Status::kFailed) std::cerr << "systole: " << job.name << ": " << r.error << "\n";
  send_result(fd, r);
  std::fflush(nullptr);
  ::_exit(r.status == JobResult::Status::kFailed ? r.exit_code : 0);
}

}  // namespace

int rasterizer_threads(std::size_t job_count, const BatchOptions& options) {
  const bool in_children = !(job_count == 1 && !options.several);
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  // Several renders share the cores: llvmpipe's threads per context default to all cores,
  // which would oversubscribe them.
  const unsigned sharing = in_children && options.parallel > 1 ? static_cast<unsigned>(options.parallel) : 1u;
  return static_cast<int>(std::max(1u, cores / sharing));
}

std::vector<JobResult> run_jobs(const std::vector<Job>& jobs, const BatchOptions& options,
                                const std::function<void(const JobResult&)>& on_done) {
  std::vector<JobResult> results(jobs.size());
  if (jobs.size() == 1 && !options.several) {
    results[0] = run_job(jobs[0], options);
    on_done(results[0]);
    return results;
  }
  struct Running {
    std::size_t job;
    int fd;
  };
  std::map<pid_t, Running> running;
  std::size_t next = 0;
  const std::size_t parallel = static_cast<std::size_t>(std::max(1, options.parallel));
  while (next < jobs.size() || !running.empty()) {
    while (next < jobs.size() && running.size() < parallel) {
      int fds[2];
      if (::pipe(fds) != 0) throw Error(ExitCode::kInternal, std::string("pipe: ") + std::strerror(errno));
      std::fflush(nullptr);  // Or the child would print this process's buffered output again.
      const pid_t pid = ::fork();
      if (pid < 0) throw Error(ExitCode::kInternal, std::string("fork: ") + std::strerror(errno));
      if (pid == 0) {
        ::close(fds[0]);
        run_child(jobs[next], options, fds[1]);
      }
      ::close(fds[1]);
      running[pid] = {next++, fds[0]};
    }
    int status = 0;
    const pid_t pid = ::waitpid(-1, &status, 0);
    if (pid < 0) {
      if (errno == EINTR) continue;
      throw Error(ExitCode::kInternal, std::string("waitpid: ") + std::strerror(errno));
    }
    const auto it = running.find(pid);
    if (it == running.end()) continue;
    JobResult& r = results[it->second.job];
    r.job = jobs[it->second.job].name;
    if (!receive_result(it->second.fd, r)) {
      r.status = JobResult::Status::kFailed;
      r.exit_code = static_cast<int>(ExitCode::kInternal);
      r.error = WIFSIGNALED(status) ? "the render process died of signal " + std::to_string(WTERMSIG(status))
                                    : "the render process exited with " + std::to_string(WEXITSTATUS(status)) +
                                          " without a result";
    }
    ::close(it->second.fd);
    running.erase(it);
    // Written by a child: this process's interrupt message names it too (common/interrupt.h).
    if (r.status == JobResult::Status::kDone) note_output_written(r.output);
    on_done(r);
  }
  return results;
}

std::string summary_table(const std::vector<JobResult>& results) {
  std::size_t width = 3;
  for (const auto& r : results) width = std::max(width, r.job.size());
  std::ostringstream out;
  char line[256];
  std::snprintf(line, sizeof line, "%-*s  %-7s  %9s  %s\n", static_cast<int>(width), "job", "status", "wall",
                "output");
  out << line;
  int counts[3] = {0, 0, 0};
  for (const auto& r : results) {
    ++counts[static_cast<int>(r.status)];
    std::snprintf(line, sizeof line, "%-*s  %-7s  %7.1f s  ", static_cast<int>(width), r.job.c_str(),
                  status_name(r.status), r.wall_s);
    out << line << (r.status == JobResult::Status::kFailed ? r.error.substr(0, r.error.find('\n')) : r.output)
        << "\n";
  }
  out << results.size() << " jobs: " << counts[0] << " done, " << counts[1] << " skipped, " << counts[2]
      << " failed\n";
  return out.str();
}

std::string result_json(const JobResult& r) {
  char wall[32];
  std::snprintf(wall, sizeof wall, "%.2f", r.wall_s);
  std::string json = "{\"job\": " + json_quote(r.job) + ", \"status\": " + json_quote(status_name(r.status)) +
                     ", \"wall_s\": " + wall + ", \"output\": " + json_quote(r.output);
  if (r.status == JobResult::Status::kFailed) {
    json += ", \"error\": " + json_quote(r.error) + ", \"exit_code\": " + std::to_string(r.exit_code);
  }
  return json + "}";
}

int batch_exit_code(const std::vector<JobResult>& results) {
  for (const auto& r : results) {
    if (r.status == JobResult::Status::kFailed) return r.exit_code;
  }
  return 0;
}

}  // namespace systole::batch

#include "analysis/figures/run_video.hpp"

#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "analysis/figures/figures.hpp"
#include "analysis/figures/map_view.hpp"
#include "geometry/voronoi_partition.hpp"

extern char** environ;

namespace covsim {

namespace fs = std::filesystem;

std::size_t video_frames(double sim_time, const VideoOptions& o) {
  const double speedup = o.speedup > 0 ? o.speedup : std::max(sim_time, 1e-9) / 20.0;
  return static_cast<std::size_t>(std::ceil(sim_time / speedup * o.fps - 1e-9)) + 1;
}

namespace {

// ffmpeg reading raw BGRA frames on its standard input.
class Encoder {
 public:
  Encoder(const fs::path& out, const std::string& container, int w, int h, double fps) {
    std::vector<std::string> args = {"ffmpeg",
                                     "-hide_banner",
                                     "-loglevel",
                                     "error",
                                     "-y",
                                     "-f",
                                     "rawvideo",
                                     "-pix_fmt",
                                     "bgra",
                                     "-s",
                                     fmt::format("{}x{}", w, h),
                                     "-r",
                                     fmt::format("{}", fps),
                                     "-i",
                                     "-"};
    if (container == "gif") {
      args.insert(args.end(),
                  {"-vf", "split[a][b];[a]palettegen[p];[b][p]paletteuse", "-f", "gif"});
    } else {
      args.insert(args.end(), {"-c:v", "libx264", "-pix_fmt", "yuv420p", "-crf", "23", "-movflags",
                               "+faststart", "-f", "mp4"});
    }
    args.push_back(out.string());
    int fds[2];
    if (pipe(fds) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[0], 0);
    posix_spawn_file_actions_addclose(&actions, fds[1]);
    std::vector<char*> argv;
    for (std::string& a : args)
      argv.push_back(a.data());
    argv.push_back(nullptr);
    const int rc = posix_spawnp(&pid_, "ffmpeg", &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    close(fds[0]);
    if (rc != 0) {
      close(fds[1]);
      throw std::runtime_error(
          rc == ENOENT ? "ffmpeg not found: videos need Debian's ffmpeg (scripts/install-deps)"
                       : std::string("cannot start ffmpeg: ") + std::strerror(rc));
    }
    fd_ = fds[1];
    // A failing ffmpeg closes the pipe: see EPIPE rather than die of SIGPIPE.
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    sigaction(SIGPIPE, &ignore, &old_);
  }
  ~Encoder() {
    if (fd_ >= 0) close(fd_);
    if (pid_ > 0) {
      int status = 0;
      waitpid(pid_, &status, 0);
    }
    sigaction(SIGPIPE, &old_, nullptr);
  }
  void write(const unsigned char* data, std::size_t size) {
    while (size > 0) {
      const ssize_t n = ::write(fd_, data, size);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) throw std::runtime_error("ffmpeg stopped reading frames (see its message above)");
      data += n;
      size -= static_cast<std::size_t>(n);
    }
  }
  void finish() {
    close(fd_);
    fd_ = -1;
    int status = 0;
    waitpid(pid_, &status, 0);
    pid_ = -1;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
      throw std::runtime_error("ffmpeg failed (see its message above)");
  }

 private:
  pid_t pid_ = -1;
  int fd_ = -1;
  struct sigaction old_ {};
};

// Each robot's trail in pixels, grown as the frames' time advances (frames come in order).
struct Trails {
  std::vector<std::vector<Vec2>> px;
  std::vector<std::size_t> next;  // each track's first record not yet in its trail
  void advance(const MapView& view, const std::vector<RobotTrack>& tracks, double t) {
    px.resize(tracks.size());
    next.resize(tracks.size(), 0);
    for (std::size_t i = 0; i < tracks.size(); ++i) {
      const std::size_t now = tracks[i].at(t);
      for (; next[i] <= now && next[i] < tracks[i].t.size(); ++next[i]) {
        const Vec2 p = view.to_px(tracks[i].position[next[i]]);
        if (px[i].empty() || distance(px[i].back(), p) > 0.5) px[i].push_back(p);
      }
    }
  }
};

void draw_frame(Canvas& c, const MapView& view, const Environment& env,
                const CellIntegrator& integrator, const std::vector<RobotTrack>& tracks,
                Trails& trails, double t, const std::string& name) {
  c.rectangle({0, 0}, {c.width(), c.height()}, Colour::hex(0xffffff));
  view.draw_background(c);
  std::vector<Vec2> virt;
  for (const RobotTrack& k : tracks)
    virt.push_back(k.virtual_generator[k.at(t)]);
  const double scale = std::clamp(c.width() / 960.0, 0.6, 2.0);
  c.push_clip(view.to_px(env.rings()));
  if (!virt.empty()) {
    const VoronoiPartition cells(integrator, virt, VoronoiPartition::Coincident::split);
    for (std::size_t i = 0; i < cells.size(); ++i) {
      const auto cell = cells.cell(i);
      if (cell.size() >= 3)
        c.stroke(view.to_px({{cell.begin(), cell.end()}}), Stroke{Colour::hex(0x1f5fbf), scale});
    }
  }
  c.pop_clip();
  // Trails above the obstacles: a walk along a wall lies on ∂Ω, half hidden by a clip to Ω.
  trails.advance(view, tracks, t);
  for (std::size_t i = 0; i < tracks.size(); ++i)
    c.polyline(trails.px[i], Stroke{robot_colour(i), 1.5 * scale});
  for (std::size_t i = 0; i < tracks.size(); ++i) {
    const RobotTrack& k = tracks[i];
    const std::size_t now = k.at(t);
    const Colour col = robot_colour(i);
    c.cross(view.to_px(k.virtual_target[now]), 3.5 * scale, Stroke{Colour::hex(0x222222), scale});
    c.square(view.to_px(k.virtual_generator[now]), 2.6 * scale, col);
    const Vec2 p = view.to_px(k.position[now]);
    c.circle(p, 4.5 * scale, col, Stroke{Colour::hex(0xffffff), scale});
    c.text(p + Vec2{5 * scale, -5 * scale}, std::to_string(i), 9 * scale, Colour::hex(0x222222));
  }
  c.text({view.axes().lo.x, view.axes().lo.y - 10 * scale},
         fmt::format("{}   t = {:.1f} s", name, t), 13 * scale, Colour::hex(0x222222));
}

}  // namespace

void write_run_video(const RunFiles& run, const fs::path& file, const VideoOptions& options) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char ch) { return std::tolower(ch); });
  if (ext != ".mp4" && ext != ".gif")
    throw std::runtime_error(file.string() + ": a video is .mp4 or .gif");
  if (!(options.fps > 0) || !(options.fps <= 240))
    throw std::runtime_error("video frame rate must be in (0, 240]");
  const Box& b = run.scenario.environment->bounds();
  const double aspect = std::clamp(b.size().y / b.size().x, 0.3, 1.6);
  // Even sizes: H.264 in yuv420p needs them.
  const int w = std::max(160, options.width) / 2 * 2;
  const double scale = w / 960.0;
  const double left = 50 * scale, top = 34 * scale, bottom = 44 * scale, right = 16 * scale;
  const int h = static_cast<int>(std::lround((w - left - right) * aspect + top + bottom)) / 2 * 2;
  const MapView view(run.scenario, {left, top}, {w - right, h - bottom});
  const std::vector<RobotTrack> tracks = run.tracks();
  const double end = run.outcome.sim_time.seconds();
  const std::size_t frames = video_frames(end, options);
  const double dt = frames > 1 ? end / static_cast<double>(frames - 1) : 0.0;
  const fs::path partial = file.string() + ".partial";
  const std::string name = scenario_name(run.scenario.source);
  try {
    Encoder encoder(partial, ext.substr(1), w, h, options.fps);
    Canvas canvas = Canvas::raster(w, h);
    const CellIntegrator integrator(*run.scenario.environment, *run.scenario.density);
    Trails trails;
    const bool tty = options.progress && isatty(2);
    for (std::size_t f = 0; f < frames; ++f) {
      draw_frame(canvas, view, *run.scenario.environment, integrator, tracks, trails,
                 std::min(end, static_cast<double>(f) * dt), name);
      const unsigned char* px = canvas.pixels();
      for (int y = 0; y < h; ++y)
        encoder.write(px + static_cast<std::ptrdiff_t>(y) * canvas.stride(),
                      static_cast<std::size_t>(w) * 4);
      if (tty) {
        const int done = static_cast<int>(40 * (f + 1) / frames);
        fmt::print(stderr, "\rvideo [{}{}] {}/{} frames", std::string(done, '#'),
                   std::string(40 - done, ' '), f + 1, frames);
      }
    }
    if (tty) fmt::print(stderr, "\n");
    encoder.finish();
  } catch (...) {
    std::error_code ec;
    fs::remove(partial, ec);
    throw;
  }
  fs::rename(partial, file);
}

}  // namespace covsim

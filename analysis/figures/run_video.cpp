#include "analysis/figures/run_video.hpp"

#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "analysis/figures/figures.hpp"
#include "analysis/figures/map_legend.hpp"
#include "analysis/figures/planner_map_view.hpp"
#include "analysis/figures/robot_palette.hpp"
#include "analysis/figures/unknown_area.hpp"
#include "geometry/voronoi_partition.hpp"
#include "sim/progress_line.hpp"

extern char** environ;

namespace covsim {

namespace fs = std::filesystem;

std::size_t video_frames(double sim_time, const VideoOptions& o) {
  const double speedup = o.speedup > 0 ? o.speedup : std::max(sim_time, 1e-9) / 20.0;
  return static_cast<std::size_t>(std::ceil(sim_time / speedup * o.fps - 1e-9)) + 1;
}

namespace {

constexpr const char* kNoFfmpeg =
    "ffmpeg not found: videos need Debian's ffmpeg (scripts/install-deps)";

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
      throw std::runtime_error(rc == ENOENT
                                   ? std::string(kNoFfmpeg)
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

// What a frame draws of the layers asked for: neither virtual paths nor the real positions'
// cells (a second partition every frame) belong in a video.
Layers frame_layers(Layers layers) {
  return layers.remove(Layer::virtual_paths).remove(Layer::real_cells);
}

// Draws frames in time order: the clock above the map, the axes around it, the legend under
// it.
class FrameDrawer {
 public:
  FrameDrawer(const Scenario& scenario, const std::vector<RobotTrack>& tracks, int width,
              const Layers& layers, const KnownCells* known, const PlannerMapRecord* maps,
              std::optional<std::uint32_t> robot)
      : scenario_(scenario),
        known_(known),
        maps_(maps != nullptr && !maps->empty() && robot ? maps : nullptr),
        robot_(robot.value_or(0)),
        tracks_(tracks),
        layers_(frame_layers(layers)),
        // Text of 14 pixels in a frame 960 wide, never under 8.
        font_(std::max(8.0, 14.0 * width / 960.0)),
        marks_{font_ / 10},
        view_(scenario),
        legend_(layers_.has(Layer::legend)
                    ? map_legend(layers_, marks_, view_, font_, known != nullptr && !known->empty(),
                                 maps_ != nullptr)
                    : Legend({}, font_)),
        integrator_(*scenario.environment, *scenario.density),
        name_(scenario_name(scenario.source)) {
    const double pad = 0.6 * font_;
    const bool axes = layers_.has(Layer::axes);
    const double top = pad + (layers_.has(Layer::title) ? 1.4 * font_ : 0);
    const double left = axes ? axes_left_room(view_.axes(), font_) : pad;
    const double bottom = axes ? axes_bottom_room(font_) : pad;
    const double map_w = width - left - pad, map_h = map_w * MapView::aspect(scenario);
    view_.place({left, top}, {left + map_w, top + map_h});
    columns_ = legend_.columns_within(width - 2 * pad);
    const double legend_h = legend_.empty() ? 0 : legend_.size(columns_).y + pad;
    legend_top_ = top + map_h + bottom;
    width_ = width;
    // Even sizes: H.264 in yuv420p needs them.
    height_ = static_cast<int>(std::lround(legend_top_ + legend_h)) / 2 * 2;
  }
  int width() const { return width_; }
  int height() const { return height_; }

  void draw(Canvas& c, double t) {
    c.rectangle({0, 0}, {c.width(), c.height()}, Colour::hex(0xffffff));
    view_.draw_background(c, layers_, font_);
    const auto has = [&](Layer l) { return layers_.has(l); };
    if (known_ != nullptr && has(Layer::obstacles)) shade_unknown(c, view_, *known_, t);
    if (has(Layer::cells) && !tracks_.empty()) {
      std::vector<Vec2> virt;
      for (const RobotTrack& k : tracks_)
        virt.push_back(k.virtual_generator[k.at(t)]);
      const VoronoiPartition cells(integrator_, virt, VoronoiPartition::Coincident::split);
      c.push_clip(view_.to_px(scenario_.environment->rings()));
      for (std::size_t i = 0; i < cells.size(); ++i) {
        const auto cell = cells.cell(i);
        if (cell.size() >= 3) c.stroke(view_.to_px({{cell.begin(), cell.end()}}), marks_.cells());
      }
      c.pop_clip();
    }
    // Trails above the obstacles: a walk along a wall lies on ∂Ω, half hidden by a clip to Ω.
    trails_.advance(view_, tracks_, t);
    if (has(Layer::paths))
      for (std::size_t i = 0; i < tracks_.size(); ++i)
        c.polyline(trails_.px[i], marks_.path(robot_colour(i)));
    if (maps_ != nullptr)
      draw_planner_map(c, view_, marks_, maps_->at(robot_, t), robot_colour(robot_));
    for (std::size_t i = 0; i < tracks_.size(); ++i) {
      const RobotTrack& k = tracks_[i];
      if (k.t.empty()) continue;
      const std::size_t now = k.at(t);
      const Colour col = robot_colour(i);
      if (has(Layer::paths)) marks_.start(c, view_.to_px(k.position[0]), col);
      if (has(Layer::targets)) marks_.target(c, view_.to_px(k.virtual_target[now]));
      if (has(Layer::generators)) marks_.generator(c, view_.to_px(k.virtual_generator[now]), col);
      if (has(Layer::targets) && k.real_target[now] != k.virtual_target[now])
        marks_.projected_target(c, view_.to_px(k.real_target[now]));
      const Vec2 p = view_.to_px(k.position[now]);
      if (has(Layer::robots))
        marks_.body(c, p, scenario_.coverage.radius * view_.px_per_metre(), col);
      if (has(Layer::ids)) marks_.id(c, p, i, 0.9 * font_);
    }
    if (has(Layer::axes)) view_.draw_scale_bar(c, font_);
    if (has(Layer::title))
      c.text({0.6 * font_, 0.6 * font_ + 1.1 * font_}, fmt::format("{}   t = {:.1f} s", name_, t),
             1.1 * font_, Marks::ink());
    if (!legend_.empty()) legend_.draw(c, {0.6 * font_, legend_top_}, columns_);
  }

 private:
  const Scenario& scenario_;
  const KnownCells* known_;
  const PlannerMapRecord* maps_;  // set when one robot's planner map is drawn
  std::uint32_t robot_;
  const std::vector<RobotTrack>& tracks_;
  Layers layers_;
  double font_;
  Marks marks_;
  MapView view_;
  Legend legend_;
  CellIntegrator integrator_;
  std::string name_;
  Trails trails_;
  int columns_ = 1, width_ = 0, height_ = 0;
  double legend_top_ = 0;
};

std::string lower_extension(const fs::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char ch) { return std::tolower(ch); });
  return ext;
}

}  // namespace

void check_video_file(const fs::path& file) {
  const std::string ext = lower_extension(file);
  if (ext != ".mp4" && ext != ".gif")
    throw std::runtime_error(file.string() + ": a video is .mp4 or .gif");
  const char* path = std::getenv("PATH");
  std::string_view dirs = path != nullptr ? path : "";
  while (true) {
    const std::size_t colon = std::min(dirs.find(':'), dirs.size());
    const fs::path dir(dirs.substr(0, colon).empty() ? "." : dirs.substr(0, colon));
    if (access((dir / "ffmpeg").c_str(), X_OK) == 0) return;
    if (colon == dirs.size()) break;
    dirs.remove_prefix(colon + 1);
  }
  throw std::runtime_error(kNoFfmpeg);
}

void write_run_video(const Scenario& scenario, const CoverageOutcome& outcome,
                     const std::vector<RobotTrack>& tracks, const fs::path& file,
                     const VideoOptions& options) {
  const std::string ext = lower_extension(file);
  if (ext != ".mp4" && ext != ".gif")
    throw std::runtime_error(file.string() + ": a video is .mp4 or .gif");
  if (!(options.fps > 0) || !(options.fps <= 240))
    throw std::runtime_error("video frame rate must be in (0, 240]");
  FrameDrawer frames_of(scenario, tracks, std::max(160, options.width) / 2 * 2, options.layers,
                        options.known, options.planner_maps, options.planner_robot);
  const int w = frames_of.width(), h = frames_of.height();
  const double end = outcome.sim_time.seconds();
  const std::size_t frames = video_frames(end, options);
  const double dt = frames > 1 ? end / static_cast<double>(frames - 1) : 0.0;
  const fs::path partial = file.string() + ".partial";
  try {
    Encoder encoder(partial, ext.substr(1), w, h, options.fps);
    Canvas canvas = Canvas::raster(w, h);
    ProgressLine line(options.progress && ProgressLine::stderr_is_terminal());
    for (std::size_t f = 0; f < frames; ++f) {
      frames_of.draw(canvas, std::min(end, static_cast<double>(f) * dt));
      const unsigned char* px = canvas.pixels();
      for (int y = 0; y < h; ++y)
        encoder.write(px + static_cast<std::ptrdiff_t>(y) * canvas.stride(),
                      static_cast<std::size_t>(w) * 4);
      if (line.due())
        line.show(fmt::format(
            "video: frame {} of {} ({:.0f}%), {:.0f} s, about {:.0f} s left", f + 1, frames,
            100.0 * static_cast<double>(f + 1) / static_cast<double>(frames), line.seconds(),
            line.seconds() / static_cast<double>(f + 1) * static_cast<double>(frames - f - 1)));
    }
    // A GIF's palette is made from every frame once they are all in: say so while it is.
    if (line.drawn()) line.show(fmt::format("video: {} frames in, ffmpeg finishing", frames));
    encoder.finish();
  } catch (...) {
    std::error_code ec;
    fs::remove(partial, ec);
    throw;
  }
  fs::rename(partial, file);
}

}  // namespace covsim

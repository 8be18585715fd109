// octopoint-view: an interactive window on a model (DESIGN.md 5). The keyboard is the event
// source of the dual-resolution renderer: L draws the coarse level while an arrow key is held, H
// the fine one at the next 100 ms tick after it is let go.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <opencv2/highgui.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "app/model_source.h"
#include "cli/arguments.h"
#include "cli/error.h"
#include "cli/numbers.h"
#include "cli/output_file.h"
#include "cli/run_tool.h"
#include "renderer/dual_resolution_renderer.h"
#include "renderer/model.h"

namespace {

namespace fs = std::filesystem;
using namespace octopoint;

constexpr const char* kUsage =
    R"(usage: octopoint-view [--model NAME | --file M.oct] [--size WxH] [--scale N]

Shows an octopoint model in a window. While an arrow key is held the coarse level turns at a fixed
speed (thread L); once it is let go the fine level is drawn at the next 100 ms tick (thread H),
and a key press aborts it at once.

  --model NAME   an embedded model (default: the default model)
  --file M.oct   a model file written by octopoint-prepare; it is validated first
  --size WxH     the rendered frame, each side 16..2048 (default 320x240)
  --scale N      the window shows each pixel as NxN, 1..8 (default 2)
  -h, --help     show this help

keys: arrows turn (90 degrees per second), + and - zoom, f toggles hole filling, r resets the view,
      s saves the frame as octopoint-view-N.png in the current directory, q or Esc quits.
The overlay shows which thread drew the frame (L or H), its drawing time and the frame rate.
highgui reports key presses only: a key counts as held while its auto-repeat keeps coming, and as
released 250 ms after its last repeat (so a tap turns the view by about 22 degrees).
)";

constexpr const char* kWindow = "octopoint-view";
constexpr Rgb kBackground{236, 236, 240};
constexpr std::int64_t kReleaseAfterUs = 250'000;

struct Options {
  std::string model_name;
  std::string model_file;
  int width = 320;
  int height = 240;
  int scale = 2;
};

Options parseOptions(int argc, char** argv) {
  Options options;
  cli::ArgumentReader args(argc, argv);
  while (args.next()) {
    if (args.is("-h") || args.is("--help")) {
      std::cout << kUsage;
      std::exit(0);
    } else if (args.is("--model")) {
      options.model_name = args.value();
    } else if (args.is("--file")) {
      options.model_file = args.value();
    } else if (args.is("--size")) {
      const cli::FrameSize size = cli::parseFrameSize(args.name(), args.value(), 16, 2048);
      options.width = size.width;
      options.height = size.height;
    } else if (args.is("--scale")) {
      options.scale = cli::parseInt(args.name(), args.value(), 1, 8);
    } else {
      args.refuseUnknown();
    }
  }
  if (!options.model_name.empty() && !options.model_file.empty()) {
    throw cli::Error("give --model or --file, not both");
  }
  return options;
}

// The window's keyboard as an event source: arrow keys are navigation keys (held while their
// auto-repeat comes), the others one-shot events; the 100 ms ticks come from the steady clock.
class KeyboardEventSource final : public EventSource {
 public:
  explicit KeyboardEventSource(const Clock& clock)
      : clock_(clock), next_tick_us_(clock.nowMicroseconds()) {}

  std::optional<ViewEvent> next(std::int32_t max_wait_ms) override {
    if (std::optional<ViewEvent> due = dueEvent()) return due;
    const int key = cv::waitKeyEx(std::max(1, max_wait_ms));
    const std::int64_t now = clock_.nowMicroseconds();
    if (key < 0) return dueEvent();
    if (const std::optional<NavigationKey> navigation = navigationKey(key)) {
      release_at_us_ = now + kReleaseAfterUs;
      if (holding_ && held_key_ != *navigation) {
        pending_press_ = ViewEvent{now, ViewEventKind::kPress, *navigation};
        const ViewEvent release{now, ViewEventKind::kRelease, held_key_};
        held_key_ = *navigation;
        return release;  // the other key goes up first; the press follows on the next call
      }
      holding_ = true;
      held_key_ = *navigation;
      return ViewEvent{now, ViewEventKind::kPress, *navigation};  // a repeat is ignored downstream
    }
    switch (key) {
      case '+':
      case '=':
        return ViewEvent{now, ViewEventKind::kZoomIn};
      case '-':
      case '_':
        return ViewEvent{now, ViewEventKind::kZoomOut};
      case 'f':
        return ViewEvent{now, ViewEventKind::kToggleFill};
      case 'r':
        return ViewEvent{now, ViewEventKind::kReset};
      case 's':
        save_requested_ = true;
        return std::nullopt;
      case 'q':
      case 27:
        return ViewEvent{now, ViewEventKind::kQuit};
      default:
        return std::nullopt;
    }
  }

  // Whether `s` was pressed since the last call.
  bool takeSaveRequest() { return std::exchange(save_requested_, false); }

 private:
  static std::optional<NavigationKey> navigationKey(int key) {
    switch (key) {  // waitKeyEx reports X11 keysyms (GTK highgui) or Qt key codes (Qt highgui)
      case 0xff51:
      case 0x1000012:
        return NavigationKey::kYawLeft;
      case 0xff53:
      case 0x1000014:
        return NavigationKey::kYawRight;
      case 0xff52:
      case 0x1000013:
        return NavigationKey::kPitchUp;
      case 0xff54:
      case 0x1000015:
        return NavigationKey::kPitchDown;
      default:
        return std::nullopt;
    }
  }

  std::optional<ViewEvent> dueEvent() {
    const std::int64_t now = clock_.nowMicroseconds();
    if (pending_press_) return std::exchange(pending_press_, std::nullopt);
    if (holding_ && now >= release_at_us_) {
      holding_ = false;
      return ViewEvent{now, ViewEventKind::kRelease, held_key_};
    }
    if (now >= next_tick_us_) {
      next_tick_us_ +=
          kTickPeriodMicroseconds * ((now - next_tick_us_) / kTickPeriodMicroseconds + 1);
      return ViewEvent{now, ViewEventKind::kTick};
    }
    return std::nullopt;
  }

  const Clock& clock_;
  std::int64_t next_tick_us_;
  bool holding_ = false;  // a navigation key is down (its auto-repeat keeps coming)
  NavigationKey held_key_ = NavigationKey::kYawLeft;
  std::int64_t release_at_us_ = 0;
  std::optional<ViewEvent> pending_press_;
  bool save_requested_ = false;
};

// Frames shown in the last second.
class FrameRate {
 public:
  int update(std::int64_t now_us) {
    shown_us_.push_back(now_us);
    while (!shown_us_.empty() && shown_us_.front() <= now_us - 1'000'000)
      shown_us_.erase(shown_us_.begin());
    return static_cast<int>(shown_us_.size());
  }

 private:
  std::vector<std::int64_t> shown_us_;
};

// The output-file rule of every tool (cli/output_file.h): whole or nothing, and an existing
// name that is not a regular file is refused, not replaced.
void savePng(const cv::Mat& bgr, int number) {
  const std::string name = "octopoint-view-" + std::to_string(number) + ".png";
  try {
    std::vector<std::uint8_t> png;
    if (!cv::imencode(".png", bgr, png)) throw cli::Error(name + ": cannot encode the PNG");
    cli::writeFileAtomically(name, {reinterpret_cast<const char*>(png.data()), png.size()});
  } catch (const std::exception& error) {
    cli::printError("octopoint-view", error.what());
    return;
  }
  std::printf("saved %s\n", name.c_str());
  std::fflush(stdout);
}

int run(int argc, char** argv) {
  const Options options = parseOptions(argc, argv);
  const std::unique_ptr<LoadedModel> loaded = loadModel(options.model_name, options.model_file);
  const ModelView* model = &*loaded->view;

  InteractiveConfig config;
  config.width = options.width;
  config.height = options.height;
  const SteadyClock clock;
  DualResolutionRenderer renderer(model->level(0), model->finestLevel(), clock, config);
  KeyboardEventSource keyboard(clock);
  FrameRate frame_rate;
  cv::namedWindow(kWindow, cv::WINDOW_AUTOSIZE | cv::WINDOW_GUI_NORMAL);  // no Qt toolbar
  cv::Mat rgb(options.height, options.width, CV_8UC3);
  cv::Mat bgr, shown;
  std::uint64_t shown_generation = 0;
  int saved = 0;
  while (true) {
    if (const std::optional<ViewEvent> event = keyboard.next(10)) {
      if (event->kind == ViewEventKind::kQuit) break;
      renderer.handle(*event);
    }
    FrameInfo info;
    const Framebuffer* frame = renderer.acquireLatest(&info);
    if (frame != nullptr && info.generation != shown_generation) {
      shown_generation = info.generation;
      resolveToRgb(*frame, *model, kBackground, {rgb.data, rgb.total() * 3});
      cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
      cv::resize(bgr, shown, {}, options.scale, options.scale, cv::INTER_NEAREST);
      char overlay[96];
      std::snprintf(overlay, sizeof overlay, "%s  %lld.%01lld ms  %d fps%s",
                    info.source == FrameSource::kFine ? "H" : "L",
                    static_cast<long long>(info.render_us / 1000),
                    static_cast<long long>(info.render_us / 100 % 10),
                    frame_rate.update(clock.nowMicroseconds()), info.view.fill ? "  fill" : "");
      cv::putText(shown, overlay, {8, 20}, cv::FONT_HERSHEY_SIMPLEX, 0.55, {0, 0, 0}, 3,
                  cv::LINE_AA);
      cv::putText(shown, overlay, {8, 20}, cv::FONT_HERSHEY_SIMPLEX, 0.55, {255, 255, 255}, 1,
                  cv::LINE_AA);
      cv::imshow(kWindow, shown);
    }
    if (keyboard.takeSaveRequest() && frame != nullptr) savePng(bgr, ++saved);
  }
  cv::destroyAllWindows();
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return octopoint::cli::runTool("octopoint-view", argc, argv, run); }

// watkins board stream (board_stream.hpp).
#include "board_stream.hpp"

#include <CLI/CLI.hpp>

#include <fcntl.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "beam_schedule.hpp"
#include "board_image.hpp"
#include "config_file.hpp"
#include "frame_packet.hpp"
#include "options.hpp"
#include "prepare.hpp"
#include "run_files.hpp"
#include "scene.hpp"
#include "size.hpp"
#include "turntable.hpp"
#include "usage_error.hpp"

namespace watkins::board_command {
namespace {

constexpr int Baud = 3'000'000;  // the FT231X's fastest rate, ulx3s_top's Baud

struct StreamFrame {
  std::string name;  // "scene.json" or "scene.json at 30 degrees", for messages
  std::vector<std::uint8_t> packet;
  std::size_t words = 0;
};

// The smallest power of two, at least 512 (one block RAM deep), that holds `words`: the bank
// `board build` gives the scene it builds.
int bank_words_for(std::size_t words) {
  int n = 512;
  while (static_cast<std::size_t>(n) < words) n *= 2;
  return n;
}

std::string degrees_text(double d) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", d);
  return b;
}

// Raw 8N1 at Baud, no flow control: the bytes leave as the packets hold them.
void set_serial(int fd, const std::string& port) {
  termios t{};
  if (tcgetattr(fd, &t) != 0) throw std::runtime_error("--port " + port + ": " + std::strerror(errno));
  cfmakeraw(&t);
  t.c_cflag &= ~(CSTOPB | PARENB | CRTSCTS);
  t.c_cflag |= CS8 | CLOCAL | CREAD;
  if (cfsetispeed(&t, B3000000) != 0 || cfsetospeed(&t, B3000000) != 0 || tcsetattr(fd, TCSANOW, &t) != 0)
    throw std::runtime_error("--port " + port + ": cannot set 3000000 baud 8N1: " + std::strerror(errno));
}

void write_all(int fd, const std::vector<std::uint8_t>& bytes, const std::string& port) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw std::runtime_error("--port " + port + ": write failed: " + std::strerror(errno));
    done += static_cast<std::size_t>(n);
  }
}

}  // namespace

CLI::App* add_stream_command(CLI::App* board, StreamArgs& a) {
  auto* s = board->add_subcommand("stream", "send frames of an animation to the board's host link (3 Mbaud serial)");
  s->add_option("scene", a.scenes, "scene files (JSON), one frame each; with --turntable, one scene")
      ->required()
      ->check(cli::non_empty_name());
  cli::add_file(s, "--port", a.port, "the board's serial port (e.g. /dev/ttyUSB0), or a file to write the packets to")
      ->required();
  cli::add_file(s, "--config", a.config, "the configuration the bitstream was built with (default: the first scene sized)");
  s->add_option("--turntable", a.turntable, "N frames of the scene turned about its vertical axis, 360/N degrees apart")
      ->check(cli::integer_in(1, 3600));
  s->add_option("--fps", a.fps, "frames a second sent to a serial port")->check(cli::finite_in(0.1, 60))->capture_default_str();
  s->add_flag("--loop", a.loop, "send the frames again and again until interrupted (a serial port only)");
  s->add_option("--bank-words", a.bank_words,
                "the board's scene bank in words (default: as `board build` sizes it for the first scene)")
      ->check(cli::integer_in(16, 1 << 15));
  s->add_option("--slots", a.slots, "line-buffer slots, a power of two (the deadline check)")
      ->check(cli::integer_in(1, 1024))
      ->capture_default_str();
  cli::add_shading(s, a.shading, "gouraud or phong, as the bitstream was built (default: the first scene's "
                                 "shading.mode)");
  return s;
}

int run_stream(const StreamArgs& a) {
  if (a.turntable > 0 && a.scenes.size() != 1)
    throw UsageError("--turntable: turns one scene; " + std::to_string(a.scenes.size()) + " given");
  if (a.bank_words != 0 && (a.bank_words & (a.bank_words - 1)) != 0)
    throw UsageError("--bank-words: " + std::to_string(a.bank_words) + " is not a power of two");
  if ((a.slots & (a.slots - 1)) != 0) throw UsageError("--slots: " + std::to_string(a.slots) + " is not a power of two");

  RunFiles files;
  std::vector<Scene> parsed;
  for (const std::string& path : a.scenes) {
    parsed.push_back(parse_scene_file(path));
    files.input("the scene file", path);
    files.scene_inputs(parsed.back());
  }
  files.input("the --config file", a.config);
  files.output("--port", a.port);
  struct stat st{};
  const bool exists = ::stat(a.port.c_str(), &st) == 0;
  int fd = -1;
  bool tty = false;
  if (exists && S_ISCHR(st.st_mode)) {
    fd = ::open(a.port.c_str(), O_WRONLY | O_NOCTTY);
    if (fd < 0) throw std::runtime_error("--port " + a.port + ": " + std::strerror(errno));
    tty = ::isatty(fd) != 0;
    if (!tty) {
      ::close(fd);
      fd = -1;
    }
  }
  struct Closer {
    int& fd;
    ~Closer() {
      if (fd >= 0) ::close(fd);
    }
  } closer{fd};
  if (a.loop && !tty) throw UsageError("--loop: " + a.port + " is not a serial port");

  // The board's configuration, size and bank, from the first scene (or --config, --bank-words).
  const BuildOptions opt = cli::shading_options(a.shading);
  const BuiltScene first = build_scene(parsed.front(), opt);
  const std::string first_name = a.scenes.front();
  if (!((first.width == board::HVisible && first.height == board::VVisible) ||
        (first.width == board::HVisible / 2 && first.height == board::VVisible / 2)))
    throw std::runtime_error(first_name + ": screen " + std::to_string(first.width) + "x" + std::to_string(first.height) +
                             ": the board shows 640x480 or 320x240 doubled");
  const int doubling = first.width == board::HVisible ? 1 : 2;
  const Config cfg = a.config.empty() ? size::sized_config(first) : load_config(a.config);
  int bank_words = a.bank_words;
  if (bank_words == 0) bank_words = bank_words_for(board::bank_image(prepare(first, cfg), cfg).words.size());

  // Every frame prepared, checked and packed before the port is touched.
  std::vector<StreamFrame> frames;
  const int count = a.turntable > 0 ? a.turntable : static_cast<int>(parsed.size());
  for (int k = 0; k < count; ++k) {
    StreamFrame f;
    BuiltScene scene;
    if (a.turntable > 0) {
      const double deg = 360.0 * k / a.turntable;
      f.name = first_name + " at " + degrees_text(deg) + " degrees (frame " + std::to_string(k) + ")";
      try {
        scene = k == 0 ? first : build_scene(board::turntable(parsed.front(), deg), opt);
      } catch (const std::invalid_argument& e) {
        throw std::runtime_error(e.what());
      }
    } else {
      f.name = a.scenes[static_cast<std::size_t>(k)];
      scene = k == 0 ? first : build_scene(parsed[static_cast<std::size_t>(k)], opt);
    }
    if (scene.width != first.width || scene.height != first.height)
      throw std::runtime_error(f.name + ": screen " + std::to_string(scene.width) + "x" + std::to_string(scene.height) +
                               ", not the first frame's " + std::to_string(first.width) + "x" +
                               std::to_string(first.height));
    if (scene.shading != first.shading)
      throw std::runtime_error(f.name + ": shading " + to_string(scene.shading) + ", not the first frame's " +
                               to_string(first.shading));
    PreparedScene prepared;
    board::BankImage bank;
    try {
      prepared = prepare(scene, cfg);
      bank = board::bank_image(prepared, cfg);
    } catch (const std::exception& e) {
      throw std::runtime_error(f.name + ": does not fit the board's configuration: " + e.what());
    }
    if (bank.words.size() > static_cast<std::size_t>(bank_words))
      throw std::runtime_error(f.name + ": the frame needs " + std::to_string(bank.words.size()) + " bank words (" +
                               std::to_string(bank.edges) + " edge records, " + std::to_string(bank.materials) +
                               " materials), more than the board's " + std::to_string(bank_words) +
                               "; nothing sent");
    board::BoardTiming t;
    t.doubling = doubling;
    t.line_slots = a.slots;
    const board::BeamSchedule s = board::beam_schedule(prepared, cfg, t);
    if (s.missed > 0) {
      const board::LineSlack& w = s.lines.at(s.worst);
      throw std::runtime_error(f.name + ": misses " + std::to_string(s.missed) + " line deadlines on the board (line " +
                               std::to_string(w.y) + ", slack " + std::to_string(w.slack) + " pipeline clocks)");
    }
    f.words = bank.words.size();
    f.packet = board::frame_packet(bank);
    frames.push_back(std::move(f));
  }

  std::size_t largest = 0, total = 0;
  for (const StreamFrame& f : frames) {
    largest = std::max(largest, f.packet.size());
    total += f.packet.size();
  }
  const double link_fps = 1.0 / board::packet_seconds(largest, Baud);
  std::printf("frames        %zu at %dx%d (doubling %d), edge record %d bits, bank %d words\n", frames.size(), first.width,
              first.height, doubling, cfg.edge_record_bits(first.shading), bank_words);
  std::printf("packets       %zu bytes in all, the largest %zu (%.1f ms at %d baud: the link carries %.1f frames/s)\n", total,
              largest, 1e3 * board::packet_seconds(largest, Baud), Baud, link_fps);

  if (!tty) {
    std::vector<unsigned char> bytes;
    bytes.reserve(total);
    for (const StreamFrame& f : frames) bytes.insert(bytes.end(), f.packet.begin(), f.packet.end());
    files.add(a.port, std::move(bytes));
    files.commit();
    std::printf("written       %s\n", a.port.c_str());
    return 0;
  }
  set_serial(fd, a.port);
  if (a.fps > link_fps)
    std::printf("note          --fps %g is more than the link carries; frames go back to back\n", a.fps);
  const auto period = std::chrono::duration<double>(1.0 / a.fps);
  auto next = std::chrono::steady_clock::now();
  long long sent = 0;
  do {
    for (const StreamFrame& f : frames) {
      std::this_thread::sleep_until(next);
      next += std::chrono::duration_cast<std::chrono::steady_clock::duration>(period);
      write_all(fd, f.packet, a.port);
      ++sent;
    }
    tcdrain(fd);
  } while (a.loop);
  std::printf("sent          %lld frames to %s\n", sent, a.port.c_str());
  return 0;
}

}  // namespace watkins::board_command

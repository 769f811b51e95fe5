// Every command's output through devices, FIFOs, symbolic links, standard output and closed pipes, and
// renders stopped by SIGINT, SIGTERM and SIGHUP at chosen moments: the exit code is documented, the
// error is one clear line, an existing output is untouched and nothing is left behind.
#include <catch2/catch.hpp>
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <future>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "curvescan/raster/image.h"
#include "curvescan/raster/png_io.h"
#include "run_command.h"

namespace curvescan::test {
namespace {

namespace fs = std::filesystem;

// A drawing whose PNG does not compress below a pipe's 64 KiB buffer (about 180 KiB with 12000 rectangles
// of random colours).
std::string noisy_svg(int rectangles) {
  std::mt19937 random(7);
  std::uniform_int_distribution<int> position(0, 595), channel(0, 255);
  std::string svg = R"(<svg xmlns="http://www.w3.org/2000/svg" width="600" height="600">)";
  for (int i = 0; i < rectangles; ++i) {
    svg += "<rect x='" + std::to_string(position(random)) + "' y='" + std::to_string(position(random)) +
           "' width='5' height='5' fill='rgb(" + std::to_string(channel(random)) + "," +
           std::to_string(channel(random)) + "," + std::to_string(channel(random)) + ")'/>";
  }
  return svg + "</svg>";
}

struct Scene {
  ScratchDirectory dir{"output-commands"};
  Scene() {
    write_text(dir / "in.svg", noisy_svg(12000));
    write_text(dir / "spec.json", R"({"type": "bezier", "points": [[0,0],[10,30],[40,-20],[50,10]]})");
    Image image(16, 16);
    REQUIRE(write_png(image, dir / "a.png"));
    image.pixels()[5] = Rgba8{255, 0, 0, 255};
    REQUIRE(write_png(image, dir / "b.png"));
  }
  std::string path(const std::string& name) const { return shell_quote((dir / name).string()); }
};

struct OutputCommand {
  std::string name;
  std::string arguments;  ///< before "-o OUT"
  bool png;               ///< a PNG (else JSON text)
};

std::vector<OutputCommand> output_commands(const Scene& s) {
  const std::string font = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
  return {
      {"render", "render " + s.path("in.svg"), true},
      {"text", "text Hello --font " + shell_quote(font), true},
      {"curve", "curve " + s.path("spec.json"), false},
      {"diff", "diff " + s.path("a.png") + " " + s.path("b.png"), true},
  };
}

bool is_output_of_kind(const std::string& bytes, bool png) {
  return png ? bytes.rfind("\x89PNG\r\n\x1a\n", 0) == 0 : bytes.rfind("{", 0) == 0;
}

TEST_CASE("every command writes through /dev/null and leaves the device alone", "[robustness][cli]") {
  const Scene scene;
  for (const OutputCommand& command : output_commands(scene)) {
    INFO(command.name);
    const CommandOutput run = run_curvescan(command.arguments + " -o /dev/null", scene.dir);
    // diff exits 1 when the images differ: its output was still written.
    CHECK((run.exit_code == 0 || (command.name == "diff" && run.exit_code == 1)));
    CHECK(run.err.empty());
    CHECK(fs::is_character_file("/dev/null"));
  }
}

TEST_CASE("every command reports a full device as an error (exit 3)", "[robustness][cli]") {
  if (!fs::is_character_file("/dev/full")) {
    WARN("skipped: this system has no /dev/full");
    return;
  }
  const Scene scene;
  for (const OutputCommand& command : output_commands(scene)) {
    INFO(command.name);
    const CommandOutput run = run_curvescan(command.arguments + " -o /dev/full", scene.dir);
    CHECK(run.exit_code == 3);
    CHECK_THAT(run.err, Catch::Contains("No space left on device"));
    CHECK(fs::is_character_file("/dev/full"));
  }
}

TEST_CASE("'-o -' is standard output for every command", "[robustness][cli]") {
  const Scene scene;
  for (const OutputCommand& command : output_commands(scene)) {
    if (command.name == "diff") continue;  // diff's standard output is its report; -o is the diff image only
    INFO(command.name);
    const CommandOutput run = run_curvescan(command.arguments + " -o -", scene.dir);
    CHECK(run.exit_code == 0);
    CHECK(is_output_of_kind(run.out, command.png));
    CHECK_FALSE(fs::exists(scene.dir / "-"));
  }
}

TEST_CASE("a symbolic link as output is followed and stays a link", "[robustness][cli]") {
  const Scene scene;
  for (const OutputCommand& command : output_commands(scene)) {
    INFO(command.name);
    fs::remove(scene.dir / "target");
    fs::remove(scene.dir / "link");
    write_text(scene.dir / "target", "old");
    fs::create_symlink("target", scene.dir / "link");
    const CommandOutput run = run_curvescan(command.arguments + " -o " + scene.path("link"), scene.dir);
    CHECK((run.exit_code == 0 || (command.name == "diff" && run.exit_code == 1)));
    CHECK(fs::is_symlink(scene.dir / "link"));
    CHECK(is_output_of_kind(read_text(scene.dir / "target"), command.png));
  }
}

TEST_CASE("a FIFO as output is written through, not replaced", "[robustness][cli]") {
  const Scene scene;
  for (const OutputCommand& command : output_commands(scene)) {
    INFO(command.name);
    const fs::path fifo = scene.dir / "pipe";
    fs::remove(fifo);
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    std::future<std::string> read = std::async(std::launch::async, [&] { return read_text(fifo); });
    const CommandOutput run = run_curvescan(command.arguments + " -o " + scene.path("pipe"), scene.dir);
    CHECK((run.exit_code == 0 || (command.name == "diff" && run.exit_code == 1)));
    CHECK(is_output_of_kind(read.get(), command.png));
    CHECK(fs::is_fifo(fifo));
  }
}

TEST_CASE("writing into a closed pipe is a clear error, not a SIGPIPE kill", "[robustness][cli]") {
  const Scene scene;
  // The subshell records curvescan's own exit code; head closes the pipe after one byte. The PNG is over
  // 64 KiB, more than the pipe holds, so curvescan is still writing when the pipe closes.
  const std::string line = "( " + shell_quote(curvescan_binary()) + " render " + scene.path("in.svg") +
                           " -o - 2>" + scene.path("err.txt") + "; echo $? >" + scene.path("status.txt") +
                           " ) | head -c1 >/dev/null";
  REQUIRE(std::system(line.c_str()) != -1);
  CHECK(read_text(scene.dir / "status.txt") == "3\n");
  CHECK_THAT(read_text(scene.dir / "err.txt"), Catch::Contains("cannot write to standard output: Broken pipe"));
}

// execv's argument vector: `binary`, then `arguments`, then the null that ends it (pointing into both).
std::vector<char*> exec_arguments(const std::string& binary, const std::vector<std::string>& arguments) {
  std::vector<char*> argv{const_cast<char*>(binary.c_str())};
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  return argv;
}

// Runs curvescan with `arguments` (one per element) and its standard output on a pipe whose reading end
// is closed before it starts, so every write fails with EPIPE whatever the output's size; its standard
// error goes to `error_file`. Returns its exit code, or 1000 + N when signal N ended it.
int run_into_closed_pipe(const std::vector<std::string>& arguments, const fs::path& error_file) {
  int ends[2];
  REQUIRE(::pipe(ends) == 0);
  ::close(ends[0]);
  const std::string binary = curvescan_binary();
  std::vector<char*> argv = exec_arguments(binary, arguments);
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int error = ::open(error_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(ends[1], 1);
    ::dup2(error, 2);
    ::execv(binary.c_str(), argv.data());
    ::_exit(127);
  }
  ::close(ends[1]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 1000 + WTERMSIG(status);
}

TEST_CASE("diff's report into a closed pipe is an error of diff naming the broken pipe",
          "[robustness][cli]") {
  // The text and JSON reports go through std::cout, which main() checks at the end; the message must name
  // the command and the reason like every other output error (docs/limits.md, "Output files").
  const Scene scene;
  for (const bool json : {false, true}) {
    std::vector<std::string> arguments{"diff", (scene.dir / "a.png").string(),
                                       (scene.dir / "b.png").string()};
    if (json) arguments.push_back("--json");
    CAPTURE(json);
    CHECK(run_into_closed_pipe(arguments, scene.dir / "err.txt") == 3);
    CHECK(read_text(scene.dir / "err.txt") ==
          "curvescan diff: error: cannot write to standard output: Broken pipe\n");
  }
}

TEST_CASE("every command's '-o -' into a closed pipe is exit 3 with one line naming the broken pipe",
          "[robustness][cli]") {
  const Scene scene;
  const std::vector<std::vector<std::string>> commands{
      {"render", (scene.dir / "in.svg").string(), "-o", "-"},
      {"text", "Hello", "--font", "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", "-o", "-"},
      {"curve", (scene.dir / "spec.json").string(), "-o", "-"},
      {"curve", (scene.dir / "spec.json").string()},
  };
  for (const std::vector<std::string>& arguments : commands) {
    CAPTURE(arguments);
    CHECK(run_into_closed_pipe(arguments, scene.dir / "err.txt") == 3);
    CHECK(read_text(scene.dir / "err.txt") ==
          "curvescan " + arguments.front() + ": error: cannot write to standard output: Broken pipe\n");
  }
}

// Starts curvescan with `arguments` (one per element), its standard streams on /dev/null.
pid_t start_curvescan(const std::vector<std::string>& arguments) {
  const std::string binary = curvescan_binary();
  std::vector<char*> argv = exec_arguments(binary, arguments);
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int null = ::open("/dev/null", O_RDWR);
    ::dup2(null, 0);
    ::dup2(null, 1);
    ::dup2(null, 2);
    ::execv(binary.c_str(), argv.data());
    ::_exit(127);
  }
  return pid;
}

// wait_exit_code's value for a process ended by signal N: kKilledBySignal + N.
constexpr int kKilledBySignal = 1000;

int wait_exit_code(pid_t pid) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : kKilledBySignal + WTERMSIG(status);
}

TEST_CASE("a render stopped by a signal at any moment exits 128+N and leaves nothing behind", "[robustness][cli]") {
  const Scene scene;
  const std::vector<std::string> render = {"render", (scene.dir / "in.svg").string(), "-w", "3000", "-o",
                                           (scene.dir / "out.png").string()};
  write_text(scene.dir / "out.png", "the old output");
  const auto start = std::chrono::steady_clock::now();
  REQUIRE(wait_exit_code(start_curvescan(render)) == 0);
  const auto whole = std::chrono::steady_clock::now() - start;
  const std::set<std::string> files = directory_listing(scene.dir);

  // Thirty moments spread over the whole run, the last ones near its end where the PNG is written.
  const int signals[] = {SIGTERM, SIGINT, SIGHUP};
  int stopped = 0;
  for (int attempt = 0; attempt < 30; ++attempt) {
    const int signal_number = signals[attempt % 3];
    INFO("attempt " << attempt << ", signal " << signal_number);
    write_text(scene.dir / "out.png", "the old output");
    const pid_t pid = start_curvescan(render);
    std::this_thread::sleep_for(whole * (attempt + 1) / 31);
    ::kill(pid, signal_number);
    const int exit_code = wait_exit_code(pid);
    // 128+N from the handler; or, for a signal that arrives before main() installed it (a slow start under
    // a sanitizer), the default action's kill, which a shell reports as 128+N too: nothing was written
    // then, and the checks below hold all the same.
    const bool killed_before_handlers = exit_code == kKilledBySignal + signal_number;
    CHECK((exit_code == 128 + signal_number || killed_before_handlers || exit_code == 0));
    // Stopped before the rename: the old file; after it (the signal came while the program was ending):
    // the whole new PNG. Never anything in between.
    const bool old_file = read_text(scene.dir / "out.png") == "the old output";
    const bool whole_png = static_cast<bool>(read_png(scene.dir / "out.png"));
    CHECK((old_file || whole_png));
    if (exit_code == 0) CHECK(whole_png);
    if (exit_code != 0) ++stopped;
    CHECK(directory_listing(scene.dir) == files);
  }
  CHECK(stopped > 0);  // the moments do fall inside the run
}

}  // namespace
}  // namespace curvescan::test

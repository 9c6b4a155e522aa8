// The command line's file layer (sim/run_files) and option layer (sim/options), tested by category
// rather than by example: every subcommand x every input it reads x every output it writes, every
// option of each malformed-value class, every way an output can fail. Each category is a table
// iterated in a loop, each case named by SCOPED_TRACE with its command line.
//
// What every case asserts besides its exit code: stderr is exactly the lines the run promises (one
// line for a refused command line), and the scratch folder is as it was (no file written, none
// changed, no ".NAME.tmpPID" temporary left) — a snapshot of names, sizes and modification times.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "cli_run.hpp"

namespace {

namespace fs = std::filesystem;
using Args = std::vector<std::string>;

struct Outcome {
  int code = -1;
  std::string out, err;
};

std::string shell_quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// The command line as a shell would take it, for SCOPED_TRACE and messages.
std::string shown(const Args& args) {
  std::string s = "watkins";
  for (const std::string& a : args)
    s += " " + (a.empty() || a.find_first_of(" ,'\"") != std::string::npos ? shell_quoted(a) : a);
  return s;
}

size_t lines(const std::string& s) {
  size_t n = 0;
  for (char c : s) n += c == '\n';
  return n + (!s.empty() && s.back() != '\n');
}

bool starts_with(const std::string& s, const std::string& p) { return s.compare(0, p.size(), p) == 0; }
bool ends_with(const std::string& s, const std::string& p) {
  return s.size() >= p.size() && s.compare(s.size() - p.size(), p.size(), p) == 0;
}

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

bool on_path(const std::string& tool) { return std::system(("command -v " + tool + " >/dev/null 2>&1").c_str()) == 0; }

// A scene that reads every kind of file a scene can name: an OBJ mesh, an STL mesh and a raw
// volume, beside a tessellated sphere with "u"/"v" (what `sweep` retessellates). 16 x 16 pixels,
// Phong's eq. 3 at the vertices so the analytic truth (the sphere's) exists: every subcommand runs
// it in milliseconds.
const char* kScene = R"({"screen": {"width": 16, "height": 16},
 "camera": {"type": "lookat", "eye": [0, 0, -60], "target": [0, 0, 0], "up": [0, 1, 0], "fov_deg": 30,
            "near": 10, "far": 200},
 "light": {"type": "directional", "direction": [-1, 1, -1]},
 "shading": {"rule": "phong"},
 "objects": [
  {"type": "sphere", "radius": 5, "u": 6, "v": 3},
  {"type": "mesh", "file": "m.obj", "normals": "average", "translate": [0, 0, 5]},
  {"type": "mesh", "file": "m.stl", "translate": [0, 0, 5]},
  {"type": "voxels", "file": "v.raw", "dims": [4, 4, 4], "threshold": 128, "translate": [8, 0, 0]}
 ]})";

// A folder `synth --rtl-dir` takes: the package, one block and a top that instantiates it with
// every parameter the flow sets, so a whole yosys + nextpnr run takes a second or two.
const char* kRtlPkg = "package watkins_pkg;\n  localparam int Tiny = 1;\nendpackage\n";
const char* kRtlBlock =
    "module edge_incrementer (input logic clk_i, input logic [1:0] a_i, output logic [1:0] y_o);\n"
    "  always_ff @(posedge clk_i) y_o <= a_i + 2'd1;\nendmodule\n";
const char* kRtlTop =
    "module watkins_top #(\n"
    "  parameter int MaxActiveEdges = 1, MaxWidth = 1, Phong = 0, XIntBits = 1, XFracBits = 1, DepthIntBits = 1,\n"
    "  DepthFracBits = 1, AttrIntBits = 1, AttrFracBits = 1, DepthBits = 1, PolyIdBits = 1, MaterialIdBits = 1,\n"
    "  EdgeIdBits = 1, EdgeOrder = 1, Smoothing = 1\n"
    ") (input logic clk_i, input logic [1:0] a_i, output logic [1:0] y_o);\n"
    "  edge_incrementer u (.clk_i(clk_i), .a_i(a_i), .y_o(y_o));\nendmodule\n";

class CliFiles : public ::testing::Test, protected watkins::test::ScratchDir {
 protected:
  void SetUp() override {
    write("s.json", kScene);
    write("m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    write("m.stl", "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
                   "endloop\nendfacet\nendsolid t\n");
    std::string raw(64, '\0');  // 4 x 4 x 4, the inner 2 x 2 x 2 inside
    for (int z = 1; z < 3; ++z)
      for (int y = 1; y < 3; ++y)
        for (int x = 1; x < 3; ++x) raw[x + 4 * (y + 4 * z)] = char(200);
    write("v.raw", raw);
    write("c.json", "{}\n");
    write("vb.json", read_bytes(WATKINS_SOURCE_DIR "/scenes/voxel_beaded.json"));
    fs::create_directory(dir_ + "/rtl");
    write("rtl/watkins_pkg.sv", kRtlPkg);
    write("rtl/edge_incrementer.sv", kRtlBlock);
    write("rtl/watkins_top.sv", kRtlTop);
    fs::create_directory(dir_ + "/sub");   // for ./sub/../NAME spellings
    fs::create_directory(dir_ + "/fold");  // an output that is a folder
    char tmpl[] = "/tmp/watkins_test_io_XXXXXX";  // captured output and synth's --work, outside dir_
    ASSERT_NE(mkdtemp(tmpl), nullptr);
    io_ = tmpl;
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(io_, ec);
  }

  // `watkins` with `command_line` as the shell splits it, run in the scratch folder under `env`
  // (VAR=value ...), stdout and stderr apart; a run killed by a signal is 128 + the signal.
  Outcome run_shell(const std::string& command_line, const std::string& env = "") const {
    const std::string cmd = "cd " + shell_quoted(dir_) + " && timeout 120 env " + env + " " + shell_quoted(WATKINS_CLI) +
                            " " + command_line + " >" + shell_quoted(io_ + "/out") + " 2>" + shell_quoted(io_ + "/err");
    const int status = std::system(cmd.c_str());
    Outcome r;
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : WIFSIGNALED(status) ? 128 + WTERMSIG(status) : -1;
    r.out = read_bytes(io_ + "/out");
    r.err = read_bytes(io_ + "/err");
    return r;
  }
  Outcome run(const Args& args, const std::string& env = "") const {
    std::string line;
    for (const std::string& a : args) line += (line.empty() ? "" : " ") + shell_quoted(a);
    return run_shell(line, env);
  }

  // Every name under the scratch folder (links not followed) with its type, size and mtime.
  std::map<std::string, std::string> snapshot() const {
    std::map<std::string, std::string> s;
    for (const auto& e : fs::recursive_directory_iterator(dir_)) {
      struct stat st {};
      ::lstat(e.path().c_str(), &st);
      s[fs::relative(e.path(), dir_).string()] = std::to_string(st.st_mode) + " " + std::to_string(st.st_size) + " " +
                                                  std::to_string(st.st_mtim.tv_sec) + "." +
                                                  std::to_string(st.st_mtim.tv_nsec);
    }
    return s;
  }
  // The names in `after` that are not in `before` or differ, and those gone.
  static std::string changes(const std::map<std::string, std::string>& before,
                             const std::map<std::string, std::string>& after) {
    std::string c;
    for (const auto& [name, what] : after) {
      const auto it = before.find(name);
      if (it == before.end()) c += " +" + name;
      else if (it->second != what) c += " ~" + name;
    }
    for (const auto& [name, what] : before)
      if (!after.count(name)) c += " -" + name;
    return c;
  }

  // A refused command line: exit code 2, nothing on stdout, one line "watkins: usage: ..." on
  // stderr holding `needle`, and nothing written.
  void expect_usage(const Args& args, const std::string& needle) {
    SCOPED_TRACE(shown(args));
    const auto before = snapshot();
    const Outcome r = run(args);
    EXPECT_EQ(r.code, 2) << r.out << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(lines(r.err), 1u) << r.err;
    EXPECT_TRUE(starts_with(r.err, "watkins: usage: ")) << r.err;
    EXPECT_NE(r.err.find(needle), std::string::npos) << "expected \"" << needle << "\" in: " << r.err;
    EXPECT_EQ(changes(before, snapshot()), "");
  }

  // synth's arguments for a run on the scratch RTL: one block on one target, its work folder
  // outside the scratch folder; `without` leaves out the option a case gives itself.
  Args synth_args(const std::string& without = "") const {
    Args a{"synth", "--rtl-dir", "rtl", "--work", io_ + "/work"};
    for (const auto& [option, value] : {std::pair<const char*, const char*>{"--designs", "edge_incrementer"},
                                        {"--targets", "ice40-up5k"}})
      if (option != without) a.insert(a.end(), {option, value});
    return a;
  }

  // The names a case gives an input `path` (relative to the scratch folder): itself, through a
  // `..`, a hard link and a symbolic link to it (made here, once).
  std::vector<std::string> spellings(const std::string& path) {
    std::string flat = path;
    for (char& c : flat) c = c == '/' ? '_' : c;
    if (!fs::exists(dir_ + "/hl_" + flat)) {
      fs::create_hard_link(dir_ + "/" + path, dir_ + "/hl_" + flat);
      fs::create_symlink(path, dir_ + "/sl_" + flat);
    }
    return {path, "./sub/../" + path, "hl_" + flat, "sl_" + flat};
  }

  std::string io_;
};

struct Input {
  std::string kind, path;
};

// Each subcommand: its arguments (every input kind it reads given), its file outputs, its inputs.
struct Reader {
  std::string name;
  Args args;
  std::vector<std::string> outputs;
  std::vector<Input> inputs;
};

const Input kSceneIn{"scene", "s.json"}, kConfigIn{"configuration", "c.json"}, kObjIn{"OBJ mesh", "m.obj"},
    kStlIn{"STL mesh", "m.stl"}, kRawIn{"raw volume", "v.raw"}, kPkgIn{"RTL package", "rtl/watkins_pkg.sv"},
    kBlockIn{"RTL module", "rtl/edge_incrementer.sv"};

// 1. An output naming an input, by any name, is refused before anything runs and the input is
// left byte for byte and time for time as it was.
TEST_F(CliFiles, AnOutputNamingAnInputIsRefusedInEveryCommand) {
  const std::vector<Reader> readers = {
      {"render", {"render", "s.json", "--config", "c.json"}, {"--out", "--diff", "--truth", "--truth-diff"},
       {kSceneIn, kConfigIn, kObjIn, kStlIn, kRawIn}},
      {"sweep", {"sweep", "s.json", "--tess", "1", "--shadings", "flat", "-q"}, {"--csv", "--md"},
       {kSceneIn, kObjIn, kStlIn, kRawIn}},
      {"size", {"size", "s.json"}, {"--out"}, {kSceneIn, kObjIn, kStlIn, kRawIn}},
      {"voxel-compare", {"voxel-compare", "s.json", "--repeat", "1", "--weights", "0.8"}, {"--md"},
       {kSceneIn, kObjIn, kStlIn, kRawIn}},
      {"export-stl", {"export-stl", "s.json"}, {"--out"}, {kSceneIn, kObjIn, kStlIn, kRawIn}},
      {"synth", synth_args(), {"--md", "--csv"}, {kConfigIn, kPkgIn, kBlockIn}},
  };
  Args synth_with_config = readers.back().args;
  synth_with_config.insert(synth_with_config.end(), {"--config", "c.json"});
  int cases = 0;
  for (const Reader& cmd : readers)
    for (const Input& in : cmd.inputs) {
      const std::string bytes = contents(in.path);
      struct stat before_st {};
      ::stat((dir_ + "/" + in.path).c_str(), &before_st);
      for (const std::string& option : cmd.outputs)
        for (const std::string& name : spellings(in.path)) {
          Args args = cmd.name == "synth" ? synth_with_config : cmd.args;
          args.insert(args.end(), {option, name});
          SCOPED_TRACE(cmd.name + " x " + in.kind + ": " + shown(args));
          const auto before = snapshot();
          const Outcome r = run(args);
          ++cases;
          EXPECT_EQ(r.code, 2) << r.out << r.err;
          EXPECT_EQ(r.out, "") << "refused before the run";
          EXPECT_EQ(lines(r.err), 1u) << r.err;
          EXPECT_TRUE(starts_with(r.err, "watkins: usage: " + option + " " + name + " is ")) << r.err;
          EXPECT_TRUE(ends_with(r.err, "; refusing to overwrite it\n")) << r.err;
          EXPECT_EQ(contents(in.path), bytes);
          struct stat st {};
          ::stat((dir_ + "/" + in.path).c_str(), &st);
          EXPECT_EQ(st.st_mtim.tv_sec, before_st.st_mtim.tv_sec);
          EXPECT_EQ(st.st_mtim.tv_nsec, before_st.st_mtim.tv_nsec);
          EXPECT_EQ(changes(before, snapshot()), "");
        }
    }
  EXPECT_EQ(cases, (5 * 4 + 4 * 2 + 4 + 4 + 4 + 3 * 2) * 4);
}

// 2. Two outputs naming one file, however spelled, are refused before anything is written.
TEST_F(CliFiles, TwoOutputsNamingOneFileAreRefused) {
  struct Writer {
    Args args;
    std::vector<std::string> outputs;
  };
  const std::vector<Writer> writers = {
      {{"render", "s.json"}, {"--out", "--diff", "--truth", "--truth-diff"}},
      {{"sweep", "s.json", "--tess", "1", "--shadings", "flat", "-q"}, {"--csv", "--md"}},
      {synth_args(), {"--md", "--csv"}},
  };
  write("e.out", "keep\n");
  fs::create_hard_link(dir_ + "/e.out", dir_ + "/he.out");
  fs::create_symlink("e.out", dir_ + "/se.out");
  fs::create_symlink("o.out", dir_ + "/so.out");  // dangling: names the file o.out would be
  // (first name, second name): one file spelled two ways.
  const std::vector<std::pair<std::string, std::string>> pairs = {
      {"o.out", "o.out"}, {"o.out", "./sub/../o.out"}, {"e.out", "he.out"}, {"e.out", "se.out"},
      {"o.out", "so.out"}, {"so.out", "o.out"}};
  for (const Writer& w : writers)
    for (size_t i = 0; i < w.outputs.size(); ++i)
      for (size_t j = i + 1; j < w.outputs.size(); ++j)
        for (const auto& [a, b] : pairs) {
          Args args = w.args;
          args.insert(args.end(), {w.outputs[i], a, w.outputs[j], b});
          expect_usage(args, "name the same file");
        }
  EXPECT_EQ(contents("e.out"), "keep\n");
}

// An output named by a symbolic link is written where the link points, as a shell's redirection
// writes it: the link stays a link, its target gets the image (a dangling link's target is made).
TEST_F(CliFiles, AnOutputNamedByALinkIsWrittenThroughIt) {
  write("old.png", "old\n");
  fs::create_symlink("old.png", dir_ + "/to_old.png");
  fs::create_symlink("new.png", dir_ + "/to_new.png");  // dangling
  for (const std::string& link : {"to_old.png", "to_new.png"}) {
    SCOPED_TRACE(link);
    const Outcome r = run({"render", "s.json", "--out", link});
    EXPECT_EQ(r.code, 0) << r.out << r.err;
    EXPECT_TRUE(fs::is_symlink(dir_ + "/" + link));
  }
  for (const char* target : {"old.png", "new.png"}) {
    SCOPED_TRACE(target);
    EXPECT_TRUE(starts_with(contents(target), "\x89PNG"));
  }
}

// A table inside the --images folder the run makes is written there, whatever the options' order.
TEST_F(CliFiles, ATableInsideTheImagesFolderTheRunMakesIsWritten) {
  const std::vector<Args> runs = {
      {"sweep", "s.json", "--tess", "1", "--shadings", "flat", "-q", "--md", "im1/t.md", "--images", "im1"},
      {"voxel-compare", "s.json", "--repeat", "1", "--weights", "0.8", "--md", "im2/t.md", "--images", "im2"}};
  for (const Args& args : runs) {
    SCOPED_TRACE(shown(args));
    const Outcome r = run(args);
    EXPECT_EQ(r.code, 0) << r.out << r.err;
    const std::string folder = args[args.size() - 1];
    EXPECT_NE(contents(folder + "/t.md").find("| "), std::string::npos);  // a table
    EXPECT_TRUE(fs::exists(dir_ + "/" + folder + "/s_truth.png"));
  }
}

// A file of an --images folder is an output too: another output of that name is refused, not
// silently replaced by the image (or the image by it).
TEST_F(CliFiles, AnOutputNamingAFileOfTheImagesFolderIsRefused) {
  fs::create_directory(dir_ + "/im");
  for (const Args& args :
       {Args{"sweep", "s.json", "--tess", "1", "--shadings", "flat", "-q", "--images", "im", "--csv", "im/s_truth.png"},
        Args{"sweep", "s.json", "--tess", "1", "--shadings", "flat", "-q", "--images", "im", "--md", "im/s_flat_6x3.png"},
        Args{"voxel-compare", "s.json", "--repeat", "1", "--weights", "0.8", "--images", "im", "--md", "im/s_flat.png"},
        Args{"voxel-compare", "s.json", "--repeat", "1", "--weights", "0.8", "--images", "im", "--md",
             "./im/s_truth.png"}}) {
    SCOPED_TRACE(shown(args));
    const auto before = snapshot();
    const Outcome r = run(args);
    EXPECT_EQ(r.code, 2) << r.out << r.err;
    EXPECT_NE(r.err.find("watkins: usage: --images file and --"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("name the same file"), std::string::npos) << r.err;
    EXPECT_EQ(changes(before, snapshot()), "");
  }
}

// 3. A write that fails exits 1 and leaves nothing: not the output, not the run's other outputs,
// no temporary. A missing folder or a folder in an output's place fails before the run.
struct FailingWriter {
  std::string name;
  Args args;
  std::vector<std::pair<std::string, std::string>> outputs;  // option, a name it writes
};

TEST_F(CliFiles, AFailingWriteLeavesNothing) {
  const std::vector<FailingWriter> writers = {
      {"render", {"render", "s.json"}, {{"--out", "a.png"}, {"--diff", "d.png"}, {"--truth", "t.png"}, {"--truth-diff", "td.png"}}},
      {"sweep", {"sweep", "s.json", "--tess", "1", "--shadings", "flat", "-q"}, {{"--csv", "c.csv"}, {"--md", "m.md"}}},
      {"size", {"size", "s.json"}, {{"--out", "o.json"}}},
      {"voxel-compare", {"voxel-compare", "vb.json", "--repeat", "1", "--weights", "0.8"}, {{"--md", "m.md"}}},
      {"export-stl", {"export-stl", "s.json"}, {{"--out", "x.stl"}}},
      {"synth", synth_args(), {{"--md", "m.md"}, {"--csv", "c.csv"}}},
  };
  for (const FailingWriter& w : writers)
    for (size_t i = 0; i < w.outputs.size(); ++i) {
      const std::string& option = w.outputs[i].first;
      // Every other output is given a good name: none of them may be written either.
      const auto with = [&](const std::string& failing) {
        Args args = w.args;
        for (size_t j = 0; j < w.outputs.size(); ++j)
          args.insert(args.end(), {w.outputs[j].first, j == i ? failing : w.outputs[j].second});
        return args;
      };
      if (w.name != "synth") {  // synth writes only after its tools ran: SynthFailingWriteLeavesNothing
        const Args args = with("/dev/full");
        SCOPED_TRACE(w.name + " " + option + ": " + shown(args));
        const auto before = snapshot();
        const Outcome r = run(args);
        EXPECT_EQ(r.code, 1) << r.err;
        EXPECT_EQ(lines(r.err), 1u) << r.err;
        EXPECT_NE(r.err.find("watkins: error: /dev/full: cannot write: No space left on device"), std::string::npos)
            << r.err;
        EXPECT_EQ(changes(before, snapshot()), "") << "no output and no temporary";
      }
      for (const auto& [failing, message] :
           {std::pair<std::string, std::string>{"nofolder/" + w.outputs[i].second,
                                                ": cannot write: its folder nofolder: No such file or directory"},
            {"nofolder/deeper/" + w.outputs[i].second,
             ": cannot write: its folder nofolder/deeper: No such file or directory"},
            {"fold", ": cannot write: it is a folder"},
            {"./sub/..", ": cannot write: it is a folder"}}) {
        const Args args = with(failing);
        SCOPED_TRACE(w.name + " " + option + ": " + shown(args));
        const auto before = snapshot();
        const Outcome r = run(args);
        EXPECT_EQ(r.code, 1) << r.err;
        EXPECT_EQ(r.out, "") << "fails before the run";
        EXPECT_EQ(r.err, "watkins: error: " + option + " " + failing + message + "\n");
        EXPECT_FALSE(fs::exists(io_ + "/work")) << "synth ran no tool";
        EXPECT_EQ(changes(before, snapshot()), "");
      }
    }
}

// --images must be a folder: a file in its place fails before the run and is left as it was.
TEST_F(CliFiles, AnImagesFolderThatIsAFileFailsBeforeTheRun) {
  write("im", "not a folder\n");
  for (const Args& args : {Args{"sweep", "s.json", "--tess", "1", "--shadings", "flat", "-q", "--images", "im"},
                           Args{"voxel-compare", "vb.json", "--repeat", "1", "--weights", "0.8", "--images", "im"}}) {
    SCOPED_TRACE(shown(args));
    const auto before = snapshot();
    const Outcome r = run(args);
    EXPECT_EQ(r.code, 1) << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err, "watkins: error: --images im: cannot write into it: it is not a folder\n");
    EXPECT_EQ(changes(before, snapshot()), "");
  }
}

// synth writes its tables after each tool run: a failing table is exit code 1 with nothing
// written (the other table neither), not a crash.
TEST_F(CliFiles, SynthFailingWriteLeavesNothing) {
  if (!on_path("yosys") || !on_path("nextpnr-ice40")) GTEST_SKIP() << "yosys or nextpnr-ice40 is not on PATH";
  for (const auto& [failing, other] : {std::pair<const char*, const char*>{"--md", "--csv"}, {"--csv", "--md"}}) {
    Args args = synth_args();
    args.insert(args.end(), {failing, "/dev/full", other, "table.txt"});
    SCOPED_TRACE(shown(args));
    const auto before = snapshot();
    const Outcome r = run(args);
    EXPECT_EQ(r.code, 1) << r.out << r.err;
    EXPECT_TRUE(ends_with(r.err, "watkins: error: /dev/full: cannot write: No space left on device\n")) << r.err;
    EXPECT_EQ(changes(before, snapshot()), "") << "no table and no temporary";
  }
}

// render --trace (with --rtl) is an output like the others, where the build has the RTL.
TEST_F(CliFiles, RenderTraceIsAnOutputLikeTheOthers) {
  const Args rtl{"render", "s.json", "--config", "c.json", "--rtl", "--trace"};
  Args probe = rtl;
  probe.push_back("s.json");
  const Outcome p = run(probe);
  if (p.err.find("this build has no RTL simulation") != std::string::npos ||
      starts_with(p.err, "watkins: usage: --trace: "))
    GTEST_SKIP() << p.err;
  for (const Input& in : {kSceneIn, kObjIn, kStlIn, kRawIn}) {
    const std::string bytes = contents(in.path);
    for (const std::string& name : spellings(in.path)) {
      Args args = rtl;
      args.push_back(name);
      expect_usage(args, "--trace " + name + " is ");
      EXPECT_EQ(contents(in.path), bytes);
    }
  }
  for (const std::string& name : spellings("c.json"))  // the configuration (rtl above gives --config c.json)
    expect_usage({"render", "s.json", "--config", "c.json", "--rtl", "--trace", name}, "--trace " + name + " is ");
  for (const std::string& other : {"--out", "--diff", "--truth", "--truth-diff"})
    expect_usage({"render", "s.json", "--rtl", "--trace", "w.fst", other, "./sub/../w.fst"}, "name the same file");
  // A failing trace, alone or beside the other outputs.
  for (const Args& args : {Args{"render", "s.json", "--rtl", "--trace", "/dev/full", "--out", "a.png", "--diff", "d.png"},
                           Args{"render", "s.json", "--rtl", "--trace", "w.fst", "--out", "/dev/full"}}) {
    SCOPED_TRACE(shown(args));
    const auto before = snapshot();
    const Outcome r = run(args);
    EXPECT_EQ(r.code, 1) << r.err;
    EXPECT_NE(r.err.find("cannot write: No space left on device"), std::string::npos) << r.err;
    EXPECT_EQ(changes(before, snapshot()), "") << "no output, no trace, no temporary";
  }
  for (const std::string& failing : {"nofolder/w.fst", "fold"}) {
    const Args args{"render", "s.json", "--rtl", "--trace", failing, "--out", "a.png"};
    SCOPED_TRACE(shown(args));
    const auto before = snapshot();
    const Outcome r = run(args);
    EXPECT_EQ(r.code, 1) << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_TRUE(starts_with(r.err, "watkins: error: --trace " + failing + ": cannot write: ")) << r.err;
    EXPECT_EQ(changes(before, snapshot()), "");
  }
}

// 4. Malformed values, class by class, for every option of the class.
struct Option {
  Args before;      // the subcommand and what it needs before the option
  std::string name;  // the option
};

TEST_F(CliFiles, NonFiniteNumbersAreRefusedByEveryRealOption) {
  const std::vector<Option> options = {{{"render", "s.json"}, "--smooth"},
                                       {{"render", "s.json"}, "--gap"},
                                       {{"render", "s.json"}, "--stall"},
                                       {{"sweep", "s.json"}, "--tess"},
                                       {{"voxel-compare", "vb.json"}, "--weights"}};
  for (const Option& o : options)
    for (const std::string& value : {"nan", "inf", "-inf", "1e999", "NaN", "-nan", "infinity"}) {
      Args args = o.before;
      args.insert(args.end(), {o.name, value});
      expect_usage(args, o.name + ": expected a finite number, got \"" + value + "\"");
      args = o.before;
      args.push_back(o.name + "=" + value);
      expect_usage(args, o.name + ": expected a finite number, got \"" + value + "\"");
    }
}

TEST_F(CliFiles, IntegersWithJunkAreRefusedByEveryIntegerOption) {
  const std::vector<Option> options = {
      {{"render", "s.json"}, "--max-active-edges"}, {{"render", "s.json"}, "--seed"},
      {{"sweep", "s.json"}, "--max-active-edges"},  {{"sweep", "s.json"}, "--jobs"},
      {{"sweep", "s.json"}, "--uv"},                {{"sweep", "s.json"}, "--frac-bits"},
      {{"sweep", "s.json"}, "--x-frac-bits"},       {{"sweep", "s.json"}, "--depth-frac-bits"},
      {{"voxel-compare", "vb.json"}, "--repeat"},   {synth_args(), "--jobs"},
      {synth_args(), "--timeout"}};
  const std::vector<std::string> lists = {"--uv", "--frac-bits", "--x-frac-bits", "--depth-frac-bits"};
  for (const Option& o : options)
    for (const std::string& value : {"12abc", "1e3", " 7", "7 ", "", "0x10", "+7", "4.0"}) {
      Args args = o.before;
      args.insert(args.end(), {o.name, value});
      // An empty value of a list is its one item, empty.
      const bool list = std::find(lists.begin(), lists.end(), o.name) != lists.end();
      expect_usage(args, o.name + (value.empty() && list ? ": empty item in \"\"" : ": expected an integer in ["));
    }
}

TEST_F(CliFiles, ShardsWithExtraFieldsSignsOrSpacesAreRefused) {
  for (const std::string& value : {"0/1/2", "-0/1", "+0/1", "0/ 1", " 0/1", "0/1 ", "1/1", "2/1", "0/0", "a/b", "0",
                                   "/1", "0/", ""})
    expect_usage({"sweep", "s.json", "--tess", "1", "--shard", value}, "--shard: expected i/N");
}

TEST_F(CliFiles, EmptyListItemsAreRefusedByEveryListOption) {
  // Each list option with one good item.
  const std::vector<std::pair<Option, std::string>> lists = {
      {{{"sweep", "s.json"}, "--tess"}, "1"},
      {{{"sweep", "s.json"}, "--uv"}, "4"},
      {{{"sweep", "s.json"}, "--frac-bits"}, "8"},
      {{{"sweep", "s.json"}, "--x-frac-bits"}, "8"},
      {{{"sweep", "s.json"}, "--depth-frac-bits"}, "8"},
      {{{"sweep", "s.json"}, "--shadings"}, "flat"},
      {{{"voxel-compare", "vb.json"}, "--weights"}, "0.8"},
      {{synth_args(), "--seeds"}, "1"},
      {{synth_args("--designs"), "--designs"}, "edge_incrementer"},
      {{synth_args("--targets"), "--targets"}, "ice40-up5k"},
      {{synth_args(), "--config"}, "default"}};
  for (const auto& [o, item] : lists)
    for (const std::string& value : std::vector<std::string>{item + ",," + item, item + ",", "," + item, ",", ",,"}) {
      Args args = o.before;
      args.insert(args.end(), {o.name, value});
      expect_usage(args, o.name + ": empty item in \"" + value + "\"");
    }
}

TEST_F(CliFiles, OptionsThatExcludeEachOtherAreRefusedTogether) {
  expect_usage({"sweep", "s.json", "--tess", "1", "--uv", "4"}, "--tess excludes --uv");
  expect_usage({"sweep", "s.json", "--uv", "4", "--tess", "1"}, "excludes");
  expect_usage({"render", "s.json", "--cull", "--no-cull"}, "--cull excludes --no-cull");
  expect_usage({"render", "s.json", "--no-cull", "--cull"}, "excludes");
}

TEST_F(CliFiles, EmptyFileNamesAreRefusedByEveryFileOption) {
  const std::vector<std::pair<Args, std::string>> cases = {
      {{"render", "s.json", "--out", ""}, "--out"},
      {{"render", "s.json", "--diff", ""}, "--diff"},
      {{"render", "s.json", "--truth", ""}, "--truth"},
      {{"render", "s.json", "--truth-diff", ""}, "--truth-diff"},
      {{"render", "s.json", "--config", ""}, "--config"},
      {{"render", "s.json", "--trace", ""}, "--trace"},
      {{"render", ""}, "the scene file name is empty"},
      {{"sweep", "s.json", "--csv", ""}, "--csv"},
      {{"sweep", "s.json", "--md", ""}, "--md"},
      {{"sweep", "s.json", "--images", ""}, "--images"},
      {{"sweep", ""}, "scenes"},
      {{"sweep", "s.json", ""}, "scenes"},
      {{"size", "s.json", "--out", ""}, "--out"},
      {{"size", ""}, "scene"},
      {{"voxel-compare", "vb.json", "--md", ""}, "--md"},
      {{"voxel-compare", "vb.json", "--images", ""}, "--images"},
      {{"voxel-compare", ""}, "scenes"},
      {{"export-stl", "s.json", "--out", ""}, "--out"},
      {{"export-stl", "", "--out", "x.stl"}, "scene"},
  };
  for (const auto& [args, needle] : cases) expect_usage(args, needle);
  for (const std::string& option : {"--md", "--csv", "--work", "--rtl-dir", "--config"}) {
    Args args = synth_args(option);
    if (option == "--work" || option == "--rtl-dir") args = {"synth", "--designs", "edge_incrementer"};
    args.insert(args.end(), {option, ""});
    expect_usage(args, option + ": ");
  }
  // The = form gives the same empty name.
  expect_usage({"render", "s.json", "--out="}, "--out");
  expect_usage({"export-stl", "s.json", "--out="}, "--out");
}

// 5. A scene that cannot be read is bad input (exit code 1) in every subcommand that reads
// scenes, one line naming it, and nothing is written.
TEST_F(CliFiles, AnUnreadableSceneIsExitOneWithNothingWritten) {
  write("bad.json", "{\"screen\": {\"width\": 16,");
  write("scalar.json", "42");
  const std::vector<Args> commands = {
      {"render", "SCENE", "--out", "a.png", "--diff", "d.png"},
      {"sweep", "SCENE", "--tess", "1", "--shadings", "flat", "-q", "--csv", "c.csv", "--md", "m.md", "--images", "im"},
      {"sweep", "s.json", "SCENE", "--tess", "1", "--shadings", "flat", "-q", "--csv", "c.csv"},
      {"size", "SCENE", "--out", "o.json"},
      {"size", "SCENE"},  // the default output, beside the scene
      {"voxel-compare", "SCENE", "--repeat", "1", "--md", "m.md", "--images", "im"},
      {"voxel-compare", "vb.json", "SCENE", "--repeat", "1", "--md", "m.md"},
      {"export-stl", "SCENE", "--out", "x.stl"}};
  for (const std::string& scene : {"missing.json", "fold", "bad.json", "scalar.json", "sub/../missing.json"})
    for (Args args : commands) {
      for (std::string& a : args)
        if (a == "SCENE") a = scene;
      SCOPED_TRACE(shown(args));
      const auto before = snapshot();
      const Outcome r = run(args);
      EXPECT_EQ(r.code, 1) << r.out << r.err;
      EXPECT_EQ(lines(r.err), 1u) << r.err;
      EXPECT_TRUE(starts_with(r.err, "watkins: error: ")) << r.err;
      EXPECT_NE(r.err.find(scene), std::string::npos) << r.err;
      EXPECT_EQ(changes(before, snapshot()), "") << "nothing written";
    }
}

// 6. The exit-code table of docs/guide/cli.md: every example that names a command (its first
// word a subcommand) runs as written in the scratch folder, which holds what the examples name
// (s.json, m.json reading m.obj and m.stl, a malformed bad.json, a screen-space screen.json), and
// gives its row's code;
// examples that need a context no scratch folder gives are run in that context or skipped.
TEST_F(CliFiles, TheExitCodeTableOfTheGuideHolds) {
  write("m.json", kScene);
  write("bad.json", "{\"x\": {\"int_bits\": ");
  write("screen.json", R"({"screen": {"width": 16, "height": 16}, "objects": [{"type": "polygons", "polygons": [
      {"vertices": [{"x": 1, "y": 1, "depth": 0.5, "rgb": [9, 9, 9]}, {"x": 9, "y": 1, "depth": 0.5, "rgb": [9, 9, 9]},
                    {"x": 1, "y": 9, "depth": 0.5, "rgb": [9, 9, 9]}]}]}]})");
  fs::create_directory(dir_ + "/broken");  // an RTL folder yosys cannot read
  write("broken/watkins_pkg.sv", kRtlPkg);
  write("broken/edge_incrementer.sv", "module edge_incrementer (input logic clk_i; endmodule\n");
  // code -> the backticked examples of its row.
  std::map<int, std::vector<std::string>> examples;
  {
    std::ifstream in(WATKINS_SOURCE_DIR "/docs/guide/cli.md");
    bool in_section = false;
    for (std::string line; std::getline(in, line);) {
      if (starts_with(line, "## ")) in_section = line == "## Exit codes";
      if (!in_section || line.size() < 5 || line[0] != '|' || line[2] < '0' || line[2] > '9' || line[3] != ' ') continue;
      const int code = line[2] - '0';
      const std::string cell = line.substr(line.rfind('|', line.size() - 2) + 1);
      for (size_t a = cell.find('`'); a != std::string::npos; a = cell.find('`', cell.find('`', a + 1) + 1)) {
        const size_t b = cell.find('`', a + 1);
        if (b == std::string::npos) break;
        examples[code].push_back(cell.substr(a + 1, b - a - 1));
      }
    }
  }
  ASSERT_EQ(examples.size(), 3u) << "rows 1, 2 and 3 with examples";
  const bool rtl_build = run({"render", "s.json", "--rtl", "--model", "float"}).err.find("no RTL simulation") ==
                         std::string::npos;
  const bool tools = on_path("yosys") && on_path("nextpnr-ice40");
  const std::vector<std::string> subcommands = {"render", "sweep", "size", "export-stl", "voxel-compare", "synth"};
  int ran = 0;
  std::string skipped;
  for (const auto& [code, list] : examples) {
    int synth_seen = 0;
    for (const std::string& example : list) {
      const std::string first = example.substr(0, example.find(' '));
      if (std::find(subcommands.begin(), subcommands.end(), first) == subcommands.end()) continue;  // `--rtl`, `PATH`
      SCOPED_TRACE("exit code " + std::to_string(code) + ": `" + example + "`");
      std::string line = example, env;
      if (code == 1 && example == "synth") {
        // The first `synth` of the row: without yosys on PATH; the second: a tool run that fails.
        if (synth_seen++ == 0) {
          env = "PATH=/nonexistent";
          line = "synth --rtl-dir rtl --designs edge_incrementer --targets ice40-up5k --work " + shell_quoted(io_ + "/w");
        } else if (!tools) {
          skipped += " `synth` (a failing tool run: yosys or nextpnr-ice40 not on PATH);";
          continue;
        } else {
          line = "synth --rtl-dir broken --designs edge_incrementer --targets ice40-up5k --work " +
                 shell_quoted(io_ + "/w");
        }
      } else if (code == 1 && example == "export-stl") {  // of a scene with no world-space surface
        line = "export-stl screen.json --out x.stl";
      } else if ((code == 1 && example == "sweep --rtl") || (code == 3 && example == "render --rtl")) {
        skipped += " `" + example + "` (an RTL that differs from its model);";
        continue;
      } else if (code == 2 && example == "render --rtl" && rtl_build) {
        skipped += " `render --rtl` (this build has the RTL);";
        continue;
      }
      const auto before = snapshot();
      const Outcome r = run_shell(line, env);
      ++ran;
      EXPECT_EQ(r.code, code) << line << "\n" << r.out << r.err;
      if (code == 2) {
        EXPECT_EQ(lines(r.err), 1u) << r.err;
        EXPECT_TRUE(starts_with(r.err, "watkins: usage: ")) << r.err;
      }
      if (code == 1 && first != "synth") EXPECT_TRUE(starts_with(r.err, "watkins: error: ")) << r.err;
      EXPECT_EQ(changes(before, snapshot()), "") << "a failed run writes nothing";
    }
  }
  EXPECT_GE(ran, 20);
  if (!skipped.empty()) std::printf("skipped:%s\n", skipped.c_str());
  // 0: help, for the program and every subcommand.
  for (const std::string& s : {"", "render", "sweep", "size", "export-stl", "voxel-compare", "synth"}) {
    const Outcome r = run_shell(s + " --help");
    EXPECT_EQ(r.code, 0) << s << r.err;
    EXPECT_EQ(r.err, "") << s;
  }
}

}  // namespace

// Interruption and failure part-way, the tools run as processes: SIGTERM and SIGINT in the middle
// of a run remove every temporary (beside the outputs and in TMPDIR) and exit 143 and 130; a failure
// after a first output was written (the plotter's) leaves no output at all; a full disk (a file-size
// limit, and a real full tmpfs where one can be mounted) gives one line naming the output, status 1,
// and no partial file; a scan's memory does not grow with its number of poses.
#include "hostile_fixtures.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace revolve {
namespace {

using ::testing::HasSubstr;
using testing::kPoleScene;
using testing::kSpinningSensor;
using testing::lineCount;
using testing::ProcessOptions;
using testing::ProcessResult;
using testing::readWholeFile;
using testing::RunningProcess;
using testing::runProcess;
using testing::ScratchDirectory;
using ::testing::StartsWith;

const std::string kLidar = REVOLVE_LIDAR_PATH, kRender = REVOLVE_RENDER_PATH, kTrace = REVOLVE_TRACE_PATH,
                  kClearance = REVOLVE_CLEARANCE_PATH;

// Waits (up to 30 s) until `dir` holds a file whose name starts with `prefix` and that has at least
// `bytes`: the tool is then writing it.
bool waitForFile(const ScratchDirectory& dir, const std::string& prefix, std::uintmax_t bytes,
                 RunningProcess& process) {
  for (int i = 0; i < 3000; ++i) {
    for (const std::string& name : dir.entries()) {
      std::error_code code;
      if (name.rfind(prefix, 0) == 0 && std::filesystem::file_size(dir / name, code) >= bytes && !code) return true;
    }
    if (process.ended()) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

TEST(Signals, ALidarRunStoppedWhileWritingLeavesNoTemporaryAndExits128PlusTheSignal) {
  for (const auto& [signal, status] : {std::pair{SIGTERM, 143}, std::pair{SIGINT, 130}}) {
    SCOPED_TRACE(signal == SIGTERM ? "SIGTERM" : "SIGINT");
    const ScratchDirectory dir, temporary;
    dir.write("scene.json", kPoleScene);
    dir.write("sensor.json", kSpinningSensor);
    dir.write("poses.csv", testing::manyPoses(2000));  // 57.6 million beams: many seconds of work
    dir.write("scan.pcd", "an existing scan");
    const std::set<std::string> before = dir.entries();
    RunningProcess lidar(
        kLidar,
        {"scene.json", "--sensor", "sensor.json", "--poses", "poses.csv", "-o", "scan.pcd", "--plot", "scan.png"},
        ProcessOptions{.directory = dir.path().string(), .environment = {"TMPDIR=" + temporary.path().string()}});
    ASSERT_TRUE(waitForFile(dir, "scan.pcd.tmp-", 1 << 20, lidar)) << "the scan never started: " << lidar.errSoFar();
    EXPECT_FALSE(temporary.entries().empty()) << "the plot's data is being written to TMPDIR";
    lidar.signal(signal);
    const ProcessResult result = lidar.finish(30);
    EXPECT_EQ(result.status, status) << result.err;
    EXPECT_EQ(dir.entries(), before) << "a temporary was left beside the output";
    EXPECT_EQ(readWholeFile(dir / "scan.pcd"), "an existing scan");
    EXPECT_TRUE(temporary.entries().empty()) << "a temporary was left in TMPDIR";
  }
}

TEST(Signals, ARenderStoppedMidwayLeavesNoTemporaryAndExits143) {
  const ScratchDirectory dir;
  dir.write("scene.json", kPoleScene);
  const std::set<std::string> before = dir.entries();
  RunningProcess render(kRender, {"scene.json", "-o", "out.png", "--width", "640", "--height", "480", "--spp", "4096"},
                        ProcessOptions{.directory = dir.path().string()});
  ASSERT_TRUE(waitForFile(dir, "out.png.tmp-", 0, render)) << render.errSoFar();
  std::this_thread::sleep_for(std::chrono::milliseconds(100));  // into the rendering
  render.signal(SIGTERM);
  const ProcessResult result = render.finish(30);
  EXPECT_EQ(result.status, 143) << result.err;
  EXPECT_EQ(dir.entries(), before);
}

// The scan is complete before the plot is drawn; when the plotter then fails (here: a matplotlib
// that cannot be imported, put first on its PYTHONPATH), neither output is written.
TEST(AllOrNone, APlotThatFailsAfterTheScanLeavesNoScanEither) {
  const ScratchDirectory dir, python;
  std::filesystem::create_directory(python / "matplotlib");
  python.write("matplotlib/__init__.py", "raise ImportError('injected failure')\n");
  dir.write("scene.json", kPoleScene);
  dir.write("sensor.json", testing::kPlanarSensor);
  dir.write("old.csv", "an existing scan");
  const std::set<std::string> before = dir.entries();
  for (const char* output : {"old.csv", "new.csv"}) {
    const ProcessResult run = runProcess(
        kLidar, {"scene.json", "--sensor", "sensor.json", "-o", output, "--plot", "plot.png"},
        ProcessOptions{.directory = dir.path().string(), .environment = {"PYTHONPATH=" + python.path().string()}}, 60);
    EXPECT_EQ(run.status, 1) << run.err;
    EXPECT_EQ(lineCount(run.err), 1u) << run.err;
    EXPECT_THAT(run.err, StartsWith("revolve-lidar: plot.png: revolve-lidar-plot failed: "));
    EXPECT_THAT(run.err, HasSubstr("injected failure"));
    EXPECT_EQ(dir.entries(), before) << output;
    EXPECT_EQ(readWholeFile(dir / "old.csv"), "an existing scan");
  }
}

// A write that fails part-way, as on a full disk: here the kernel's file-size limit (EFBIG).
TEST(FullDisk, AFailedWriteIsOneLineNamingTheOutputAndLeavesNoPartialFile) {
  const ScratchDirectory dir;
  dir.write("scene.json", kPoleScene);
  dir.write("sensor.json", kSpinningSensor);
  dir.write("poses.csv", testing::manyPoses(40));  // 25 MB of binary PCD
  dir.write("scan.pcd", "an existing scan");
  dir.write("image.exr", "an existing image");
  dir.write("image.png", "an existing image");
  const std::set<std::string> before = dir.entries();
  const ProcessResult lidar = runProcess(
      kLidar,
      {"scene.json", "--sensor", "sensor.json", "--poses", "poses.csv", "-o", "scan.pcd", "--pcd-data", "binary"},
      ProcessOptions{.directory = dir.path().string(), .fileSizeLimit = 1 << 20}, 60);
  EXPECT_EQ(lidar.status, 1);
  EXPECT_EQ(lidar.err, "revolve-lidar: scan.pcd: write failed: File too large\n");
  const ProcessResult render =
      runProcess(kRender, {"scene.json", "-o", "image.exr", "--width", "256", "--height", "192"},
                 ProcessOptions{.directory = dir.path().string(), .fileSizeLimit = 4096}, 60);
  EXPECT_EQ(render.status, 1);
  EXPECT_EQ(lineCount(render.err), 1u) << render.err;
  EXPECT_THAT(render.err, StartsWith("revolve-render: image.exr: write failed: "));
  // A PNG (6.5 KB at this size) went through OpenImageIO's PNG writer, which ignored the failure.
  const ProcessResult png = runProcess(kRender, {"scene.json", "-o", "image.png", "--width", "256", "--height", "192"},
                                       ProcessOptions{.directory = dir.path().string(), .fileSizeLimit = 4096}, 60);
  EXPECT_EQ(png.status, 1);
  EXPECT_EQ(png.err, "revolve-render: image.png: write failed: File too large\n");
  EXPECT_EQ(dir.entries(), before) << "a partial file or a temporary was left";
  EXPECT_EQ(readWholeFile(dir / "scan.pcd"), "an existing scan");
  EXPECT_EQ(readWholeFile(dir / "image.exr"), "an existing image");
  EXPECT_TRUE(readWholeFile(dir / "image.png") == "an existing image") << "the old image was replaced";
}

// The same on a file system that is really full: a 256 KiB tmpfs mounted in a private mount
// namespace (root or user namespaces needed; skipped where neither is available).
TEST(FullDisk, AFullFileSystemIsOneLineNamingTheOutputAndLeavesNoPartialFile) {
  const ScratchDirectory dir;
  dir.write("scene.json", kPoleScene);
  dir.write("sensor.json", kSpinningSensor);
  dir.write("poses.csv", testing::manyPoses(40));
  std::filesystem::create_directory(dir / "full");
  const std::string script =
      "mount -t tmpfs -o size=256k revolve-full full 2>/dev/null || exit 77\n"
      "printf 'an existing scan' > full/scan.pcd\n"
      "\"$1\" scene.json --sensor sensor.json --poses poses.csv -o full/scan.pcd --pcd-data binary\n"
      "status=$?\n"
      "ls -A full; cat full/scan.pcd; exit $status\n";
  ProcessResult run =
      runProcess("/usr/bin/unshare", {"--mount", "--propagation", "private", "/bin/sh", "-c", script, "sh", kLidar},
                 ProcessOptions{.directory = dir.path().string()}, 60);
  if (run.status == 77 || run.err.rfind("unshare:", 0) == 0) {
    run =
        runProcess("/usr/bin/unshare", {"--user", "--map-root-user", "--mount", "/bin/sh", "-c", script, "sh", kLidar},
                   ProcessOptions{.directory = dir.path().string()}, 60);
  }
  if (run.status == 77 || run.err.rfind("unshare:", 0) == 0) GTEST_SKIP() << "cannot mount a tmpfs here: " << run.err;
  EXPECT_EQ(run.status, 1);
  EXPECT_EQ(run.err, "revolve-lidar: full/scan.pcd: write failed: No space left on device\n");
  EXPECT_EQ(run.out, "scan.pcd\nan existing scan") << "only the old scan, as it was";
}

// Runs `tool args` in `dir` with full/ a file system that is really full: a 64 KiB tmpfs mounted in
// a private mount namespace (root, or a user namespace), holding an existing `output` and a filler
// taking every other byte, so that the tool's first write there fails. stdout ends with a listing
// of full/ and the output's contents after the run. nullopt where no tmpfs can be mounted.
std::optional<ProcessResult> runOnAFullFileSystem(const ScratchDirectory& dir, const std::string& tool,
                                                  const std::string& output, const std::vector<std::string>& args,
                                                  const std::vector<std::string>& environment = {}) {
  std::filesystem::create_directories(dir / "full");
  const std::string script =
      "mount -t tmpfs -o size=64k revolve-full full 2>/dev/null || exit 77\n"
      "printf 'an existing file' > \"full/$1\"\n"
      "head -c 1048576 /dev/zero > full/filler 2>/dev/null\n"
      "name=$1; shift\n"
      "\"$@\"\n"
      "status=$?\n"
      "echo '== full/'; ls -A full | grep -vx filler; cat \"full/$name\"; exit $status\n";
  std::vector<std::string> shell{"/bin/sh", "-c", script, "sh", output, tool};
  shell.insert(shell.end(), args.begin(), args.end());
  const auto unshare = [&](std::vector<std::string> namespaces) {
    namespaces.insert(namespaces.end(), shell.begin(), shell.end());
    return runProcess("/usr/bin/unshare", namespaces,
                      ProcessOptions{.directory = dir.path().string(), .environment = environment}, 120);
  };
  ProcessResult run = unshare({"--mount", "--propagation", "private"});
  if (run.status == 77 || run.err.rfind("unshare:", 0) == 0) run = unshare({"--user", "--map-root-user", "--mount"});
  if (run.status == 77 || run.err.rfind("unshare:", 0) == 0) return std::nullopt;
  return run;
}

struct FullDiskCase {
  std::string tool, name, output;  // the tool, its name in messages, the output on the full disk (in full/)
  std::vector<std::string> args;
};

// Every output format of every tool, written on a full file system: status 1, one line naming the
// output and the cause, the existing file as it was, nothing else written (outputs of the same run
// elsewhere included). OpenImageIO's PNG writer, given the file by name, ignored the failed writes
// and the render reported success with a short, undecodable PNG in place of the old one.
TEST(FullDisk, EveryOutputOfEveryToolOnAFullFileSystemFailsInOneLineAndLeavesItAsItWas) {
  const ScratchDirectory dir;
  dir.write("scene.json", kPoleScene);
  dir.write("sensor.json", testing::kPlanarSensor);
  dir.write("poses.csv", testing::kPoses);
  dir.write("profile.csv", "r,z\n0,0\n1,0\n1,1\n0,1\n");
  dir.write("rays.csv", "ox,oy,oz,dx,dy,dz,tnear,tfar\n-4,0,0.5,1,0,0,0,inf\n");
  dir.write("curve.csv", "r,z\n0,0\n0.5,0\n1,0.5\n0.5,1\n0,1\n");
  std::vector<FullDiskCase> cases = {
      {kRender,
       "revolve-render",
       "image.png",
       {"scene.json", "-o", "full/image.png", "--width", "64", "--height", "48"}},
      {kRender,
       "revolve-render",
       "image.exr",
       {"scene.json", "-o", "full/image.exr", "--width", "64", "--height", "48"}},
      {kRender, "revolve-render", "stats.json", {"scene.json", "-o", "image.png", "--stats", "full/stats.json"}},
      {kRender, "revolve-render", "scene.pov", {"scene.json", "--export-pov", "full/scene.pov"}},
      {kRender, "revolve-render", "scene.pov", {"scene.json", "--export-pov", "full/scene.pov", "-o", "image.png"}},
      {kTrace,
       "revolve-trace",
       "hits.csv",
       {"--profile", "profile.csv", "--rays", "rays.csv", "--out", "full/hits.csv"}},
      {kTrace,
       "revolve-trace",
       "hits.csv",
       {"--profile", "curve.csv", "--spline", "quadratic", "--rays", "rays.csv", "--out", "full/hits.csv"}},
      {kLidar,
       "revolve-lidar",
       "scan.csv",
       {"scene.json", "--sensor", "sensor.json", "--poses", "poses.csv", "-o", "full/scan.csv"}},
      {kLidar,
       "revolve-lidar",
       "scan.pcd",
       {"scene.json", "--sensor", "sensor.json", "-o", "full/scan.pcd", "--pcd-data", "binary"}},
      {kLidar, "revolve-lidar", "scan.pcd", {"scene.json", "--sensor", "sensor.json", "-o", "full/scan.pcd"}},
      {kLidar,
       "revolve-lidar",
       "plot.png",
       {"scene.json", "--sensor", "sensor.json", "-o", "scan.csv", "--plot", "full/plot.png"}},
      {kClearance,
       "revolve-clearance",
       "clearance.csv",
       {"scene.json", "--robot", "0.3,0,1.5", "--poses", "poses.csv", "-o", "full/clearance.csv"}},
  };
#ifdef REVOLVE_LIDAR_BENCH_PATH
  cases.push_back({REVOLVE_LIDAR_BENCH_PATH,
                   "revolve-lidar-bench",
                   "bench.json",
                   {"scene.json", "--poses", "poses.csv", "--out", "full/bench.json", "--repeats", "1"}});
#endif
#ifdef REVOLVE_BENCH_PATH
  for (const char* option : {"--json", "--csv"}) {
    const std::string output = option == std::string("--json") ? "bench.json" : "bench.csv";
    cases.push_back({REVOLVE_BENCH_PATH,
                     "revolve-bench",
                     output,
                     {"--quick", "--rays", "8", "--camera", "4x2", "--repetitions", "1", option, "full/" + output,
                      "speed-error", "--shapes", "sphere"}});
  }
#endif
  const std::set<std::string> before = dir.entries();
  for (const FullDiskCase& c : cases) {
    std::string command = c.name;
    for (const std::string& arg : c.args) command += " " + arg;
    SCOPED_TRACE(command);
    const std::optional<ProcessResult> run = runOnAFullFileSystem(dir, c.tool, c.output, c.args);
    if (!run) GTEST_SKIP() << "cannot mount a tmpfs here";
    EXPECT_EQ(run->status, 1) << run->err;
    // The plotter writes the plot itself and fails as Python does; every other write is the tool's.
    if (c.output == "plot.png") {
      EXPECT_EQ(lineCount(run->err), 1u) << run->err;
      EXPECT_THAT(run->err, ::testing::StartsWith(c.name + ": full/" + c.output + ": "));
      EXPECT_THAT(run->err, ::testing::HasSubstr("No space left on device"));
    } else if (c.name == "revolve-bench") {  // its progress goes to stderr too
      EXPECT_THAT(run->err, ::testing::EndsWith("\n" + c.name + ": full/" + c.output +
                                                ": write failed: No space left on device\n"));
    } else {
      EXPECT_EQ(run->err, c.name + ": full/" + c.output + ": write failed: No space left on device\n");
    }
    EXPECT_THAT(run->out, ::testing::EndsWith("== full/\n" + c.output + "\nan existing file"))
        << "only the old file, as it was";
    std::set<std::string> after = dir.entries();
    after.erase("full");
    EXPECT_EQ(after, before) << "an output of the same run was written elsewhere, or a temporary left";
  }
}

// The issue as a user met it: an 8 KiB tmpfs holding an old image; the new one does not fit.
TEST(FullDisk, APngThatDoesNotFitLeavesTheOldOneAndFailsInOneLine) {
  const ScratchDirectory dir;
  dir.write("scene.json", kPoleScene);
  std::filesystem::create_directory(dir / "small");
  const std::string script =
      "mount -t tmpfs -o size=8k revolve-small small 2>/dev/null || exit 77\n"
      "printf OLD > small/z.png\n"
      "\"$1\" scene.json -o small/z.png --width 200 --height 150 --spp 1 --threads 1\n"
      "status=$?\n"
      "ls -A small; cat small/z.png; exit $status\n";
  ProcessResult run =
      runProcess("/usr/bin/unshare", {"--mount", "--propagation", "private", "/bin/sh", "-c", script, "sh", kRender},
                 ProcessOptions{.directory = dir.path().string()}, 60);
  if (run.status == 77 || run.err.rfind("unshare:", 0) == 0) {
    run =
        runProcess("/usr/bin/unshare", {"--user", "--map-root-user", "--mount", "/bin/sh", "-c", script, "sh", kRender},
                   ProcessOptions{.directory = dir.path().string()}, 60);
  }
  if (run.status == 77 || run.err.rfind("unshare:", 0) == 0) GTEST_SKIP() << "cannot mount a tmpfs here: " << run.err;
  EXPECT_EQ(run.status, 1);
  EXPECT_EQ(run.err, "revolve-render: small/z.png: write failed: No space left on device\n");
  EXPECT_TRUE(run.out == "z.png\nOLD") << "the old image was replaced";
}

// The scan is streamed: 80 poses take no more memory than 40 (the whole table of 40 more poses
// would be 40 x 28,800 beams x 28 bytes = 32 MB), and the binary PCD holds every point in PCL's
// 31-byte layout. Not from fewer poses: under AddressSanitizer the allocator itself warms up over
// the first dozens of poses (clang 19, measured: 4 poses 29.9 MB, 40 poses 35.3 MB, 400 poses
// 36.8 MB; the Release build 13.5 MB at all three), which is not the scan growing.
TEST(Streaming, AScansMemoryDoesNotGrowWithItsPoses) {
  const ScratchDirectory dir;
  dir.write("scene.json", kPoleScene);
  dir.write("sensor.json", kSpinningSensor);
  long peak[2] = {0, 0};
  const int poses[2] = {40, 80};
  // Under AddressSanitizer, freed blocks wait in a quarantine (they would count as growth): off.
  const char* asan = std::getenv("ASAN_OPTIONS");
  const std::string asanOptions =
      "ASAN_OPTIONS=" + std::string(asan != nullptr ? std::string(asan) + ":" : "") + "quarantine_size_mb=0";
  for (int i = 0; i < 2; ++i) {
    dir.write("poses.csv", testing::manyPoses(poses[i]));
    const ProcessResult run =
        runProcess(REVOLVE_PEAK_MEMORY_PATH,
                   {dir / "peak.txt", kLidar, "scene.json", "--sensor", "sensor.json", "--poses", "poses.csv", "-o",
                    "scan.pcd", "--pcd-data", "binary"},
                   ProcessOptions{.directory = dir.path().string(), .environment = {asanOptions}}, 60);
    ASSERT_EQ(run.status, 0) << run.err;
    peak[i] = std::stol(readWholeFile(dir / "peak.txt"));
    std::filesystem::remove(dir / "peak.txt");
    const std::string cloud = readWholeFile(dir / "scan.pcd");
    const std::size_t data = cloud.find("DATA binary\n");
    ASSERT_NE(data, std::string::npos);
    EXPECT_EQ(cloud.size() - (data + 12), std::size_t(poses[i]) * 28800 * 31);  // 31 bytes a point (io/scan_files.h)
  }
  const long tableKb = 40L * 28800 * 28 / 1024;  // io::BeamReturn: 7 four-byte fields
  EXPECT_LT(peak[1] - peak[0], tableKb / 4) << "peaks " << peak[0] << " KB and " << peak[1] << " KB";
  EXPECT_GT(peak[0], 1000) << "a peak was measured";
}

}  // namespace
}  // namespace revolve

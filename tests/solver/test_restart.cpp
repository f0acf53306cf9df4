// Restart determinism: a run stopped half way
// (max_cycles) and restarted from its checkpoint ends with gauge CSVs and a
// final state identical bit for bit to the uninterrupted run, same thread
// count, for a FEM case and a particle (SPH) model. Comparing every array of
// the final checkpoints also catches state that visit_state() forgot.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <set>
#include <string>
#include <thread>

#include "case/case_fingerprint.hpp"
#include "case/case_reader.hpp"
#include "common/verification.hpp"
#include "restart_helpers.hpp"
#include "solver/run.hpp"
#include "solver/run_checkpoints.hpp"

namespace camouflet {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  return test::fresh_test_output(fs::path("restart") / name);
}

RunOptions options_for(const fs::path& out, const fs::path& case_file) {
  RunOptions o = test::quiet_run_options(out);
  o.case_fingerprint = case_fingerprint(case_file);
  return o;
}

TEST(Restart, FemRunStoppedHalfWayAndRestartedIsBitIdentical) {
  const fs::path root = scratch("fem");
  const fs::path case_file = root / "case.toml";
  test::write_text(case_file, test::restart_fem_case());
  const Model full = read_case(case_file);
  const RunSummary reference = run_model(full, options_for(root / "full", case_file));
  ASSERT_GT(reference.cycles, 100);

  // First half: the same case stopped at half the cycles.
  const std::int64_t half = reference.cycles / 2;
  test::write_text(case_file, test::restart_fem_case("max_cycles = " + std::to_string(half) + "\n"));
  const Model first = read_case(case_file);
  RunOptions o1 = options_for(root / "split", case_file);
  const RunSummary s1 = run_model(first, o1);
  EXPECT_EQ(s1.cycles, half);

  // Second half: the original case, from the latest checkpoint.
  test::write_text(case_file, test::restart_fem_case());
  const Model second = read_case(case_file);
  RunOptions o2 = options_for(root / "split", case_file);
  o2.restart = "latest";
  const RunSummary s2 = run_model(second, o2);
  EXPECT_EQ(s2.cycles, reference.cycles);
  EXPECT_EQ(s2.time, reference.time);

  EXPECT_EQ(test::read_text(root / "full" / "axis.csv"), test::read_text(root / "split" / "axis.csv"));
  EXPECT_EQ(test::read_text(root / "full" / "fields.pvd"), test::read_text(root / "split" / "fields.pvd"));
  test::expect_same_final_state(root / "full", root / "split");
}

// The column of restart_fem_case cut in two at y = 2 m by a slide surface: the pulse crosses the
// contact, and the upper half flies off when the tension arrives. Stopped while the halves press.
std::string slide_case(const std::string& extra_run = "") {
  std::string c = test::restart_fem_case(extra_run);
  const std::string block = "block = { origin = [0.0, 0.0], size = [0.5, 4.0], cells = [4, 40] }";
  c.replace(c.find(block), block.size(),
            "block = { origin = [0.0, 0.0], size = [0.5, 2.0], cells = [4, 20] }\n\n[[parts]]\nname = \"top\"\n"
            "material = \"soil\"\nblock = { origin = [0.0, 2.0], size = [0.5, 2.0], cells = [4, 20] }\n\n"
            "[[slide_surfaces]]\nparts = [\"top\"]\nfriction = 0.3\n\n[[boundary]]\ntype = \"symmetry\"\n"
            "set = \"top.xmin\"\nnormal = [1.0, 0.0]");
  return c;
}

TEST(Restart, SlideSurfaceRunStoppedHalfWayAndRestartedIsBitIdentical) {
  const fs::path root = scratch("slide");
  const fs::path case_file = root / "case.toml";
  test::write_text(case_file, slide_case());
  const RunSummary reference = run_model(read_case(case_file), options_for(root / "full", case_file));
  ASSERT_GT(reference.cycles, 100);
  test::write_text(case_file, slide_case("max_cycles = " + std::to_string(reference.cycles / 3) + "\n"));
  const RunSummary s1 = run_model(read_case(case_file), options_for(root / "split", case_file));
  EXPECT_EQ(s1.cycles, reference.cycles / 3);
  test::write_text(case_file, slide_case());
  RunOptions o2 = options_for(root / "split", case_file);
  o2.restart = "latest";
  const RunSummary s2 = run_model(read_case(case_file), o2);
  EXPECT_EQ(s2.cycles, reference.cycles);
  EXPECT_EQ(test::read_text(root / "full" / "axis.csv"), test::read_text(root / "split" / "axis.csv"));
  test::expect_same_final_state(root / "full", root / "split");
}

TEST(Restart, ChangedPhysicsKeyIsRefusedNamingTheKey) {
  const fs::path root = scratch("changed");
  const fs::path case_file = root / "case.toml";
  test::write_text(case_file, test::restart_fem_case("max_cycles = 20\n"));
  run_model(read_case(case_file), options_for(root / "out", case_file));
  // The CFL factor changes the physics: refused. The end time may change.
  test::write_text(case_file, test::restart_fem_case("max_cycles = 40\n"));
  std::string text = test::read_text(case_file);
  text.replace(text.find("cfl = 0.6"), 9, "cfl = 0.5");
  test::write_text(case_file, text);
  RunOptions o = options_for(root / "out", case_file);
  o.restart = "latest";
  try {
    run_model(read_case(case_file), o);
    FAIL() << "a changed cfl was accepted on restart";
  } catch (const InputError& e) {
    EXPECT_NE(e.message().find("key 'run.cfl' changed from 0.6 to 0.5"), std::string::npos) << e.message();
  }
}

TEST(Restart, DamagedLatestCheckpointIsRefusedAndThePreviousOneUsed) {
  const fs::path root = scratch("damaged");
  const fs::path case_file = root / "case.toml";
  test::write_text(case_file,
                   test::restart_fem_case("max_cycles = 60\n", "interval_cycles = 20\nkeep = 3\n"));
  run_model(read_case(case_file), options_for(root / "out", case_file));
  auto list = list_checkpoints(root / "out" / "checkpoints");
  ASSERT_EQ(list.size(), 3u);
  // Flip one byte inside the data of the newest: its checksum no longer
  // matches. The byte is found inside an array's stored bytes (the file's
  // middle may be padding, which no checksum covers): 64 bytes from the middle
  // of an array, varied enough to occur once in the file.
  {
    const CheckpointData data = read_checkpoint(list.front());
    std::string bytes = test::read_text(list.front());
    std::size_t flip = std::string::npos;
    for (const auto& [name, a] : data.arrays) {
      if (a.bytes.size() < 128) continue;
      const std::string needle(reinterpret_cast<const char*>(a.bytes.data()) + a.bytes.size() / 2, 64);
      if (std::set<char>(needle.begin(), needle.end()).size() < 16) continue;
      const std::size_t at = bytes.find(needle);
      if (at != std::string::npos && bytes.rfind(needle) == at) {
        flip = at + 32;
        break;
      }
    }
    ASSERT_NE(flip, std::string::npos) << "no array's bytes found in the file";
    bytes[flip] = static_cast<char>(bytes[flip] ^ 0x5a);
    test::write_text(list.front(), bytes);
  }
  EXPECT_THROW(read_checkpoint(list.front()), CheckpointError);
  // A truncated file is refused too.
  {
    const std::string bytes = test::read_text(list[1]);
    test::write_text(root / "truncated.h5", bytes.substr(0, bytes.size() / 3));
  }
  try {
    read_checkpoint(root / "truncated.h5");
    FAIL() << "a truncated checkpoint was accepted";
  } catch (const CheckpointError& e) {
    EXPECT_NE(std::string(e.what()).find("refused"), std::string::npos) << e.what();
  }
  test::write_text(case_file,
                   test::restart_fem_case("max_cycles = 80\n", "interval_cycles = 20\nkeep = 3\n"));
  RunOptions o = options_for(root / "out", case_file);
  o.restart = "latest";
  const RunSummary s = run_model(read_case(case_file), o);
  EXPECT_EQ(s.cycles, 80);
}

// Two elastic blocks of particles colliding at 40 m/s (plane strain), a gauge in the struck block.
Model particle_model(std::int64_t max_cycles) {
  Model model = test::colliding_particle_blocks(max_cycles);
  GaugeGroup group;
  group.name = "target";
  group.points.push_back({"middle", {0.06, 0.02, 0.0}, {}});
  model.gauges.push_back(group);
  return model;
}

TEST(Restart, ParticleRunStoppedHalfWayAndRestartedIsBitIdentical) {
  const fs::path root = scratch("sph");
  const test::SplitRun run = test::run_split(root, particle_model);
  ASSERT_GT(run.reference.cycles, 20);
  EXPECT_EQ(run.first.cycles, run.half);
  EXPECT_EQ(run.second.cycles, run.reference.cycles);
  EXPECT_EQ(test::read_text(root / "full" / "target.csv"), test::read_text(root / "split" / "target.csv"));
  test::expect_same_final_state(root / "full", root / "split");
}

TEST(Restart, FirstChangedKeyIsNamed) {
  EXPECT_EQ(first_changed_key("a = 1\nb = 2\n", "a = 1\nb = 2\n"), "");
  EXPECT_EQ(first_changed_key("a = 1\nb = 2\n", "a = 1\nb = 3\n"), "key 'b' changed from 2 to 3");
  EXPECT_EQ(first_changed_key("a = 1\n", "a = 1\nc = 4\n"), "key 'c' = 4 was added");
  EXPECT_EQ(first_changed_key("a = 1\nc = 4\n", "a = 1\n"), "key 'c' (was 4) is missing");
}


// A checkpoint holds the state and nothing of the moment it was written: the
// same state written twice, more than a second apart (HDF5 object headers keep
// times in whole seconds unless told not to), gives the same bytes, so two
// builds' checkpoints compare with cmp (scripts/byte-compare.sh).
TEST(Restart, SameStateWrittenTwiceGivesTheSameBytes) {
  CheckpointData data;
  set_meta(data, "cycle", "42");
  StateArray a;
  a.width = 2;
  a.count = 3;
  const double values[6] = {1.0, -2.5, 3.25, 0.0, 1e-300, 7.0};
  a.bytes.assign(reinterpret_cast<const unsigned char*>(values),
                 reinterpret_cast<const unsigned char*>(values) + sizeof(values));
  data.arrays["solver.nodes.position"] = a;
  const fs::path out = scratch("same_bytes");
  fs::create_directories(out);
  write_checkpoint(out / "first.h5", data);
  std::this_thread::sleep_for(std::chrono::milliseconds(1100));
  write_checkpoint(out / "second.h5", data);
  const bool same = test::read_text(out / "first.h5") == test::read_text(out / "second.h5");
  test::record_check("checkpoint of one state written 1.1 s apart, file bytes", "identical",
                     same ? "identical" : "differ", same);
  EXPECT_TRUE(same);
}

}  // namespace
}  // namespace camouflet

#pragma once
// A checkpoint in memory: named arrays collected from visit_state() (core/
// state_visitor.hpp), and the visitors that fill it and load it back. The
// file format (HDF5) is checkpoint_file.hpp; this part knows nothing of it.
#include <cstdint>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/state_visitor.hpp"

namespace camouflet {

// A checkpoint that cannot be used: unreadable, truncated, another format
// version, failing its checksum, or not matching the model.
class CheckpointError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct StateArray {
  StateType type = StateType::f64;
  std::size_t width = 1;
  std::size_t count = 0;
  std::vector<unsigned char> bytes;  // count * width values of type
};

struct CheckpointData {
  std::map<std::string, StateArray> arrays;
  // FNV-1a (64 bit) of each array's name, type, shape and bytes, summed over
  // the arrays so the order of the file does not matter.
  std::uint64_t checksum() const;
};

// Copies every visited array into a CheckpointData.
class StateRecorder : public StateVisitor {
 public:
  explicit StateRecorder(CheckpointData& out) : out_(out) {}
  bool loading() const override { return false; }
  void array(const std::string& name, StateType type, std::size_t width, std::size_t count, const void* data,
             const std::function<void*(std::size_t)>& resize) override;

 private:
  CheckpointData& out_;
};

// Fills every visited array from a CheckpointData; an array the checkpoint
// lacks, or one of another type or width, throws CheckpointError naming it.
// finish() refuses arrays of the checkpoint nobody asked for (names starting
// with "meta." excepted): the model has less state than the run that wrote it.
class StateLoader : public StateVisitor {
 public:
  explicit StateLoader(const CheckpointData& in) : in_(in) {}
  bool loading() const override { return true; }
  void array(const std::string& name, StateType type, std::size_t width, std::size_t count, const void* data,
             const std::function<void*(std::size_t)>& resize) override;
  void finish() const;

 private:
  const CheckpointData& in_;
  std::set<std::string> used_;
};

// Metadata arrays ("meta.<key>") as text.
void set_meta(CheckpointData& data, const std::string& key, const std::string& value);
std::string get_meta(const CheckpointData& data, const std::string& key);

}  // namespace camouflet

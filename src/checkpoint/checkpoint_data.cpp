#include "checkpoint/checkpoint_data.hpp"

#include <fmt/format.h>

#include <cstring>

namespace camouflet {

namespace {

constexpr std::uint64_t fnv_offset = 14695981039346656037ull;
constexpr std::uint64_t fnv_prime = 1099511628211ull;

std::uint64_t fnv1a(std::uint64_t h, const void* data, std::size_t n) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < n; ++i) {
    h ^= p[i];
    h *= fnv_prime;
  }
  return h;
}

}  // namespace

std::uint64_t CheckpointData::checksum() const {
  std::uint64_t sum = 0;
  for (const auto& [name, a] : arrays) {
    std::uint64_t h = fnv1a(fnv_offset, name.data(), name.size());
    const std::uint64_t shape[3] = {static_cast<std::uint64_t>(a.type), a.width, a.count};
    h = fnv1a(h, shape, sizeof shape);
    sum += fnv1a(h, a.bytes.data(), a.bytes.size());
  }
  return sum;
}

void StateRecorder::array(const std::string& name, StateType type, std::size_t width, std::size_t count,
                          const void* data, const std::function<void*(std::size_t)>&) {
  if (out_.arrays.count(name)) throw std::logic_error("state array '" + name + "' visited twice");
  StateArray& a = out_.arrays[name];
  a.type = type;
  a.width = width;
  a.count = count;
  const std::size_t n = count * width * state_type_size(type);
  a.bytes.resize(n);
  if (n) std::memcpy(a.bytes.data(), data, n);
}

void StateLoader::array(const std::string& name, StateType type, std::size_t width, std::size_t, const void*,
                        const std::function<void*(std::size_t)>& resize) {
  const auto it = in_.arrays.find(name);
  if (it == in_.arrays.end())
    throw CheckpointError(
        fmt::format("the checkpoint has no '{}' (written by another model or version)", name));
  const StateArray& a = it->second;
  if (a.type != type || a.width != width)
    throw CheckpointError(fmt::format("'{}' in the checkpoint has another type or width", name));
  void* target = resize(a.count);
  if (!a.bytes.empty()) std::memcpy(target, a.bytes.data(), a.bytes.size());
  used_.insert(name);
}

void StateLoader::finish() const {
  for (const auto& [name, a] : in_.arrays)
    if (name.rfind("meta.", 0) != 0 && !used_.count(name))
      throw CheckpointError(fmt::format("the checkpoint holds '{}', which this model does not have", name));
}

void set_meta(CheckpointData& data, const std::string& key, const std::string& value) {
  StateArray& a = data.arrays["meta." + key];
  a.type = StateType::u8;
  a.width = 1;
  a.count = value.size();
  a.bytes.assign(value.begin(), value.end());
}

std::string get_meta(const CheckpointData& data, const std::string& key) {
  const auto it = data.arrays.find("meta." + key);
  if (it == data.arrays.end()) return {};
  return std::string(it->second.bytes.begin(), it->second.bytes.end());
}

}  // namespace camouflet

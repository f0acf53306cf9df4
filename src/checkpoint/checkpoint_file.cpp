#include "checkpoint/checkpoint_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <hdf5.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <system_error>

namespace camouflet {

namespace fs = std::filesystem;

namespace {

hid_t native_type(StateType t) {
  switch (t) {
    case StateType::f64:
      return H5T_NATIVE_DOUBLE;
    case StateType::i32:
      return H5T_NATIVE_INT32;
    case StateType::i64:
      return H5T_NATIVE_INT64;
    case StateType::u32:
      return H5T_NATIVE_UINT32;
    case StateType::u64:
      return H5T_NATIVE_UINT64;
    case StateType::u8:
      return H5T_NATIVE_UINT8;
  }
  return H5T_NATIVE_UINT8;
}

// HDF5 prints its own error stack on every failed call; our messages replace it.
void quiet_hdf5() {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

[[noreturn]] void io_fail(const char* what, const fs::path& path, int err = EIO) {
  throw fs::filesystem_error(what, path, std::error_code(err, std::generic_category()));
}

void fsync_path(const fs::path& path, bool directory) {
  const int fd = ::open(path.c_str(), directory ? O_RDONLY | O_DIRECTORY : O_RDONLY);
  if (fd < 0) io_fail("cannot open for fsync", path, errno);
  const int rc = ::fsync(fd);
  const int err = errno;
  ::close(fd);
  if (rc != 0) io_fail("cannot fsync", path, err);
}

template <class T>
void write_attribute(hid_t file, const char* name, hid_t type, const T& value, const fs::path& path) {
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t attr = H5Acreate2(file, name, type, space, H5P_DEFAULT, H5P_DEFAULT);
  const bool ok = attr >= 0 && H5Awrite(attr, type, &value) >= 0;
  if (attr >= 0) H5Aclose(attr);
  H5Sclose(space);
  if (!ok) io_fail("cannot write checkpoint attribute", path);
}

struct ReadContext {
  CheckpointData* data;
  std::string error;
};

herr_t read_dataset(hid_t group, const char* name, const H5L_info_t*, void* user) {
  auto& ctx = *static_cast<ReadContext*>(user);
  const hid_t dset = H5Dopen2(group, name, H5P_DEFAULT);
  if (dset < 0) {
    ctx.error = fmt::format("dataset '{}' is unreadable", name);
    return -1;
  }
  const hid_t space = H5Dget_space(dset);
  const hid_t ftype = H5Dget_type(dset);
  hsize_t dims[2] = {0, 0};
  const int rank = space >= 0 ? H5Sget_simple_extent_ndims(space) : -1;
  if (rank == 2) H5Sget_simple_extent_dims(space, dims, nullptr);
  StateArray a;
  const H5T_class_t cls = H5Tget_class(ftype);
  const std::size_t size = H5Tget_size(ftype);
  const bool is_signed = cls == H5T_INTEGER && H5Tget_sign(ftype) == H5T_SGN_2;
  bool known = true;
  if (cls == H5T_FLOAT && size == 8)
    a.type = StateType::f64;
  else if (cls == H5T_INTEGER && size == 4)
    a.type = is_signed ? StateType::i32 : StateType::u32;
  else if (cls == H5T_INTEGER && size == 8)
    a.type = is_signed ? StateType::i64 : StateType::u64;
  else if (cls == H5T_INTEGER && size == 1 && !is_signed)
    a.type = StateType::u8;
  else
    known = false;
  bool ok = rank == 2 && known;
  if (ok) {
    a.count = dims[0];
    a.width = dims[1];
    a.bytes.resize(a.count * a.width * state_type_size(a.type));
    if (!a.bytes.empty())
      ok = H5Dread(dset, native_type(a.type), H5S_ALL, H5S_ALL, H5P_DEFAULT, a.bytes.data()) >= 0;
  }
  H5Tclose(ftype);
  if (space >= 0) H5Sclose(space);
  H5Dclose(dset);
  if (!ok) {
    ctx.error = fmt::format("dataset '{}' is unreadable or of an unknown shape", name);
    return -1;
  }
  ctx.data->arrays[name] = std::move(a);
  return 0;
}

}  // namespace

void write_checkpoint(const fs::path& path, const CheckpointData& data) {
  quiet_hdf5();
  fs::path tmp = path;
  tmp += ".tmp";
  // No creation and modification times in the object headers: the same state makes the same
  // bytes, so two runs' checkpoints compare with cmp (scripts/byte-compare.sh).
  const hid_t file_props = H5Pcreate(H5P_FILE_CREATE);
  H5Pset_obj_track_times(file_props, false);
  const hid_t file = H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, file_props, H5P_DEFAULT);
  H5Pclose(file_props);
  if (file < 0) io_fail("cannot create checkpoint", tmp, errno ? errno : EIO);
  const hid_t dataset_props = H5Pcreate(H5P_DATASET_CREATE);
  H5Pset_obj_track_times(dataset_props, false);
  bool ok = true;
  for (const auto& [name, a] : data.arrays) {
    const hsize_t dims[2] = {a.count, a.width};
    const hid_t space = H5Screate_simple(2, dims, nullptr);
    const hid_t type = native_type(a.type);
    const hid_t dset = H5Dcreate2(file, name.c_str(), type, space, H5P_DEFAULT, dataset_props, H5P_DEFAULT);
    ok = dset >= 0 &&
         (a.bytes.empty() || H5Dwrite(dset, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, a.bytes.data()) >= 0);
    if (dset >= 0) H5Dclose(dset);
    H5Sclose(space);
    if (!ok) break;
  }
  H5Pclose(dataset_props);
  if (ok) {
    const int version = checkpoint_format_version;
    const std::uint64_t sum = data.checksum();
    H5Fclose(file);
    const hid_t again = H5Fopen(tmp.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    if (again < 0) io_fail("cannot reopen checkpoint", tmp);
    try {
      write_attribute(again, "format_version", H5T_NATIVE_INT, version, tmp);
      write_attribute(again, "checksum", H5T_NATIVE_UINT64, sum, tmp);
    } catch (...) {
      H5Fclose(again);
      throw;
    }
    ok = H5Fflush(again, H5F_SCOPE_GLOBAL) >= 0;
    ok = H5Fclose(again) >= 0 && ok;
  } else {
    H5Fclose(file);
  }
  if (!ok) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    io_fail("cannot write checkpoint (disk full?)", tmp, ENOSPC);
  }
  fsync_path(tmp, false);
  fs::rename(tmp, path);
  fsync_path(path.parent_path().empty() ? fs::path(".") : path.parent_path(), true);
}

CheckpointData read_checkpoint(const fs::path& path) {
  quiet_hdf5();
  const auto refuse = [&path](const std::string& why) {
    return CheckpointError(fmt::format("checkpoint {} refused: {}", path.string(), why));
  };
  if (!fs::is_regular_file(path)) throw refuse("no such file");
  if (H5Fis_hdf5(path.c_str()) <= 0) throw refuse("not an HDF5 file (truncated or damaged)");
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) throw refuse("cannot be opened as HDF5 (truncated or damaged)");
  int version = -1;
  std::uint64_t stored = 0;
  bool ok = true;
  for (auto [name, type, target] :
       {std::tuple<const char*, hid_t, void*>{"format_version", H5T_NATIVE_INT, &version},
        {"checksum", H5T_NATIVE_UINT64, &stored}}) {
    const hid_t attr = H5Aexists(file, name) > 0 ? H5Aopen(file, name, H5P_DEFAULT) : -1;
    ok = ok && attr >= 0 && H5Aread(attr, type, target) >= 0;
    if (attr >= 0) H5Aclose(attr);
  }
  if (!ok) {
    H5Fclose(file);
    throw refuse("format_version or checksum attribute missing (an incomplete file)");
  }
  if (version != checkpoint_format_version) {
    H5Fclose(file);
    throw refuse(fmt::format("format version {}, this camouflet reads version {}", version,
                             checkpoint_format_version));
  }
  CheckpointData data;
  ReadContext ctx{&data, {}};
  const herr_t rc = H5Literate(file, H5_INDEX_NAME, H5_ITER_NATIVE, nullptr, read_dataset, &ctx);
  H5Fclose(file);
  if (rc < 0) throw refuse(ctx.error.empty() ? "cannot list its datasets" : ctx.error);
  const std::uint64_t actual = data.checksum();
  if (actual != stored)
    throw refuse(fmt::format("checksum mismatch (stored {:016x}, computed {:016x}): the file is damaged",
                             stored, actual));
  return data;
}

fs::path CheckpointSeries::write(std::int64_t cycle, const CheckpointData& data) const {
  fs::create_directories(dir_);
  const fs::path path = dir_ / fmt::format("checkpoint_{:012}.h5", cycle);
  write_checkpoint(path, data);
  const auto all = list_checkpoints(dir_);
  for (std::size_t k = static_cast<std::size_t>(std::max(keep_, 1)); k < all.size(); ++k) {
    std::error_code ignored;
    fs::remove(all[k], ignored);
  }
  return path;
}

std::vector<fs::path> list_checkpoints(const fs::path& dir) {
  std::vector<fs::path> out;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return out;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("checkpoint_", 0) == 0 && entry.path().extension() == ".h5") out.push_back(entry.path());
  }
  // Zero-padded cycle numbers: the names sort by cycle.
  std::sort(out.begin(), out.end(),
            [](const fs::path& a, const fs::path& b) { return a.filename() > b.filename(); });
  return out;
}

}  // namespace camouflet

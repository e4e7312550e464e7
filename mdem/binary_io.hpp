#pragma once
// Bit-exact binary serialisation for checkpoints (mdem/checkpoint.hpp): doubles and integers are
// stored as their bytes (little-endian machines; the checkpoint header records the byte order and
// refuses another), so a resumed run continues from exactly the saved numbers. A reader that
// runs out of data or finds a count that does not match throws InputError naming the file.
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

#include "mdem/quaternion.hpp"

namespace mesochain::mdem {

class BinaryWriter {
 public:
  template <class T>
  void write(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto* p = reinterpret_cast<const unsigned char*>(&v);
    bytes_.insert(bytes_.end(), p, p + sizeof(T));
  }
  void write(const Vec3& v) {
    for (int k = 0; k < 3; ++k) write<double>(v[k]);
  }
  void write(const Quat& q) {
    write<double>(q.w), write<double>(q.x), write<double>(q.y), write<double>(q.z);
  }
  void write(const std::string& s) {
    write<std::uint64_t>(s.size());
    bytes_.insert(bytes_.end(), s.begin(), s.end());
  }
  template <class T>
  void writeVector(const std::vector<T>& v) {
    write<std::uint64_t>(v.size());
    if constexpr (std::is_arithmetic_v<T>) {
      const auto* p = reinterpret_cast<const unsigned char*>(v.data());
      bytes_.insert(bytes_.end(), p, p + v.size() * sizeof(T));
    } else {
      for (const T& x : v) write(x);
    }
  }
  const std::vector<unsigned char>& bytes() const { return bytes_; }

 private:
  std::vector<unsigned char> bytes_;
};

class BinaryReader {
 public:
  BinaryReader(const unsigned char* data, std::size_t size, std::string source)
      : data_(data), size_(size), source_(std::move(source)) {}

  template <class T>
  T read() {
    if constexpr (std::is_same_v<T, Vec3>) {
      Vec3 v;
      for (int k = 0; k < 3; ++k) v[k] = read<double>();
      return v;
    } else if constexpr (std::is_same_v<T, Quat>) {
      Quat q;
      q.w = read<double>(), q.x = read<double>(), q.y = read<double>(), q.z = read<double>();
      return q;
    } else if constexpr (std::is_same_v<T, std::string>) {
      const std::uint64_t n = read<std::uint64_t>();
      need(n);
      std::string s(reinterpret_cast<const char*>(data_ + pos_), n);
      pos_ += n;
      return s;
    } else {
      static_assert(std::is_trivially_copyable_v<T>);
      need(sizeof(T));
      T v;
      std::memcpy(&v, data_ + pos_, sizeof(T));
      pos_ += sizeof(T);
      return v;
    }
  }
  template <class T>
  std::vector<T> readVector(const std::string& what) {
    const std::uint64_t n = read<std::uint64_t>();
    if (n > size_ - pos_) fail(what + ": a count of " + std::to_string(n) + " beyond the end of the data");
    std::vector<T> v;
    if constexpr (std::is_arithmetic_v<T>) {
      need(n * sizeof(T));
      v.resize(n);
      std::memcpy(v.data(), data_ + pos_, n * sizeof(T));
      pos_ += n * sizeof(T);
    } else {
      v.reserve(n);
      for (std::uint64_t k = 0; k < n; ++k) v.push_back(read<T>());
    }
    return v;
  }
  // Reads a count and throws unless it equals `expected` (the checkpoint is of another scene).
  void expectCount(const std::string& what, std::uint64_t expected);
  std::size_t remaining() const { return size_ - pos_; }
  [[noreturn]] void fail(const std::string& message) const;

 private:
  void need(std::size_t n) const {
    if (n > size_ - pos_) fail("data ends early (truncated checkpoint)");
  }
  const unsigned char* data_;
  std::size_t size_, pos_ = 0;
  std::string source_;
};

}  // namespace mesochain::mdem

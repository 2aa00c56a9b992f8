#include "scanners/io/byte_reader.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>

#include "scanners/core/errors.h"

namespace bespoke::io {

void Fail(const std::filesystem::path& file, const std::string& what) {
  throw InputError(file, what);
}

MappedFile::MappedFile(const std::filesystem::path& file) {
  std::error_code ec;
  const auto status = std::filesystem::status(file, ec);
  if (ec || !std::filesystem::exists(status)) Fail(file, "file not found");
  if (std::filesystem::is_directory(status)) Fail(file, "is a folder, not a scan file");
  if (!std::filesystem::is_regular_file(status)) Fail(file, "not a regular file");
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) Fail(file, std::string("cannot open: ") + std::strerror(errno));
  struct stat st {};
  if (::fstat(fd, &st) != 0) {
    const int err = errno;
    ::close(fd);
    Fail(file, std::string("cannot read: ") + std::strerror(err));
  }
  if (st.st_size == 0) {
    ::close(fd);
    Fail(file, "file is empty");
  }
  size_ = static_cast<std::size_t>(st.st_size);
  // MAP_POPULATE: fault the pages in one go (the readers touch every byte).
  void* map = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
  const int err = errno;
  ::close(fd);
  if (map == MAP_FAILED) Fail(file, std::string("cannot read: ") + std::strerror(err));
  data_ = static_cast<const char*>(map);
}

MappedFile::~MappedFile() {
  if (data_) ::munmap(const_cast<char*>(data_), size_);
}

bool LineCursor::Next(std::string_view* line) {
  if (pos_ >= text_.size()) return false;
  const std::size_t end = text_.find('\n', pos_);
  std::size_t stop = end == std::string_view::npos ? text_.size() : end;
  *line = text_.substr(pos_, stop - pos_);
  if (!line->empty() && line->back() == '\r') line->remove_suffix(1);
  pos_ = end == std::string_view::npos ? text_.size() : end + 1;
  ++next_line_;
  return true;
}

namespace {

bool IsSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

}  // namespace

std::size_t Tokenize(std::string_view line, std::vector<std::string_view>* tokens,
                     std::string_view extra_separators) {
  tokens->clear();
  auto is_sep = [&](char c) {
    return IsSpace(c) || extra_separators.find(c) != std::string_view::npos;
  };
  std::size_t i = 0;
  const std::size_t n = line.size();
  while (i < n) {
    while (i < n && is_sep(line[i])) ++i;
    if (i >= n) break;
    const std::size_t start = i;
    while (i < n && !is_sep(line[i])) ++i;
    tokens->push_back(line.substr(start, i - start));
  }
  return tokens->size();
}

std::string_view StripBom(std::string_view text) {
  return text.substr(0, 3) == "\xEF\xBB\xBF" ? text.substr(3) : text;
}

std::string_view Trim(std::string_view line) {
  while (!line.empty() && IsSpace(line.front())) line.remove_prefix(1);
  while (!line.empty() && IsSpace(line.back())) line.remove_suffix(1);
  return line;
}

bool ParseDouble(std::string_view token, double* value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty() || token.front() == '+') return false;
  const char* end = token.data() + token.size();
  const auto result = std::from_chars(token.data(), end, *value);
  return result.ec == std::errc() && result.ptr == end;
}

bool ParseInt64(std::string_view token, std::int64_t* value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty() || token.front() == '+') return false;
  const char* end = token.data() + token.size();
  const auto result = std::from_chars(token.data(), end, *value);
  return result.ec == std::errc() && result.ptr == end;
}

std::string Quote(std::string_view token) {
  std::string out = "'";
  const std::size_t n = std::min<std::size_t>(token.size(), 40);
  for (std::size_t i = 0; i < n; ++i) {
    const auto c = static_cast<unsigned char>(token[i]);
    if (c < 32 || c >= 127) {
      static const char* kHex = "0123456789abcdef";
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 15];
    } else {
      out += static_cast<char>(c);
    }
  }
  if (token.size() > n) out += "...";
  return out + "'";
}

int SizeOf(ScalarType type) {
  switch (type) {
    case ScalarType::kInt8:
    case ScalarType::kUint8:
      return 1;
    case ScalarType::kInt16:
    case ScalarType::kUint16:
      return 2;
    case ScalarType::kInt32:
    case ScalarType::kUint32:
    case ScalarType::kFloat32:
      return 4;
    case ScalarType::kFloat64:
      return 8;
  }
  return 1;
}

bool IsInteger(ScalarType type) {
  return type != ScalarType::kFloat32 && type != ScalarType::kFloat64;
}

namespace {

template <typename T>
T Load(const char* p, bool big_endian) {
  unsigned char b[sizeof(T)];
  std::memcpy(b, p, sizeof(T));
  if (big_endian) {
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
  }
  T value;
  std::memcpy(&value, b, sizeof(T));
  return value;
}

template <typename T>
void Store(std::string* out, T value, bool big_endian) {
  unsigned char b[sizeof(T)];
  std::memcpy(b, &value, sizeof(T));
  if (big_endian) {
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
  }
  out->append(reinterpret_cast<const char*>(b), sizeof(T));
}

// Converts with saturation (no undefined behaviour for out-of-range values).
template <typename T>
T Saturate(double value) {
  if (std::isnan(value)) return T(0);
  if (value <= static_cast<double>(std::numeric_limits<T>::lowest()))
    return std::numeric_limits<T>::lowest();
  if (value >= static_cast<double>(std::numeric_limits<T>::max()))
    return std::numeric_limits<T>::max();
  return static_cast<T>(std::llround(value));
}

template <typename T>
void ConvertAll(const char* src, std::int64_t stride, bool big_endian, std::int64_t count,
                double* dst) {
  if (big_endian && sizeof(T) > 1) {
    for (std::int64_t i = 0; i < count; ++i) dst[i] = Load<T>(src + i * stride, true);
  } else {
    for (std::int64_t i = 0; i < count; ++i) dst[i] = Load<T>(src + i * stride, false);
  }
}

}  // namespace

void ConvertColumn(const char* src, std::int64_t stride, ScalarType type, bool big_endian,
                   std::int64_t count, double* dst) {
  switch (type) {
    case ScalarType::kInt8:
      return ConvertAll<std::int8_t>(src, stride, false, count, dst);
    case ScalarType::kUint8:
      return ConvertAll<std::uint8_t>(src, stride, false, count, dst);
    case ScalarType::kInt16:
      return ConvertAll<std::int16_t>(src, stride, big_endian, count, dst);
    case ScalarType::kUint16:
      return ConvertAll<std::uint16_t>(src, stride, big_endian, count, dst);
    case ScalarType::kInt32:
      return ConvertAll<std::int32_t>(src, stride, big_endian, count, dst);
    case ScalarType::kUint32:
      return ConvertAll<std::uint32_t>(src, stride, big_endian, count, dst);
    case ScalarType::kFloat32:
      return ConvertAll<float>(src, stride, big_endian, count, dst);
    case ScalarType::kFloat64:
      return ConvertAll<double>(src, stride, big_endian, count, dst);
  }
}

double LoadScalar(const char* p, ScalarType type, bool big_endian) {
  switch (type) {
    case ScalarType::kInt8:
      return Load<std::int8_t>(p, false);
    case ScalarType::kUint8:
      return Load<std::uint8_t>(p, false);
    case ScalarType::kInt16:
      return Load<std::int16_t>(p, big_endian);
    case ScalarType::kUint16:
      return Load<std::uint16_t>(p, big_endian);
    case ScalarType::kInt32:
      return Load<std::int32_t>(p, big_endian);
    case ScalarType::kUint32:
      return Load<std::uint32_t>(p, big_endian);
    case ScalarType::kFloat32:
      return Load<float>(p, big_endian);
    case ScalarType::kFloat64:
      return Load<double>(p, big_endian);
  }
  return 0.0;
}

float SafeFloat(double value) {
  constexpr double kMax = std::numeric_limits<float>::max();
  if (value > kMax) return std::numeric_limits<float>::infinity();
  if (value < -kMax) return -std::numeric_limits<float>::infinity();
  return static_cast<float>(value);  // NaN stays NaN
}

std::uint32_t LoadUint32Le(const char* p) { return Load<std::uint32_t>(p, false); }

void AppendScalar(std::string* out, double value, ScalarType type, bool big_endian) {
  switch (type) {
    case ScalarType::kInt8:
      return Store(out, Saturate<std::int8_t>(value), false);
    case ScalarType::kUint8:
      return Store(out, Saturate<std::uint8_t>(value), false);
    case ScalarType::kInt16:
      return Store(out, Saturate<std::int16_t>(value), big_endian);
    case ScalarType::kUint16:
      return Store(out, Saturate<std::uint16_t>(value), big_endian);
    case ScalarType::kInt32:
      return Store(out, Saturate<std::int32_t>(value), big_endian);
    case ScalarType::kUint32:
      return Store(out, Saturate<std::uint32_t>(value), big_endian);
    case ScalarType::kFloat32:
      return Store(out, SafeFloat(value), big_endian);
    case ScalarType::kFloat64:
      return Store(out, value, big_endian);
  }
}

void AppendNumber(std::string* out, double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  out->append(buffer, result.ptr);
}

void AppendNumber(std::string* out, float value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  out->append(buffer, result.ptr);
}

void AppendNumber(std::string* out, std::int64_t value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  out->append(buffer, result.ptr);
}

}  // namespace bespoke::io

#include "pipeline/batch/done_record.h"

#include <openssl/evp.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <ctime>
#include <fstream>
#include <memory>

#include "scanners/core/build_info.h"
#include "scanners/core/errors.h"
#include "scanners/core/json_io.h"

namespace bespoke {
namespace fs = std::filesystem;
using nlohmann::json;

std::string FileSha256(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file, std::string("cannot read: ") + std::strerror(errno));
  std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> ctx(EVP_MD_CTX_new(), &EVP_MD_CTX_free);
  if (!ctx || EVP_DigestInit_ex(ctx.get(), EVP_sha256(), nullptr) != 1) {
    throw InternalError("OpenSSL SHA-256 unavailable");
  }
  std::array<char, 1 << 16> buffer;
  while (in) {
    in.read(buffer.data(), buffer.size());
    if (in.gcount() > 0)
      EVP_DigestUpdate(ctx.get(), buffer.data(), static_cast<size_t>(in.gcount()));
  }
  if (in.bad()) throw InputError(file, "read error while hashing");
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  EVP_DigestFinal_ex(ctx.get(), digest, &length);
  static const char* kHex = "0123456789abcdef";
  std::string hex;
  for (unsigned int i = 0; i < length; ++i) {
    hex += kHex[digest[i] >> 4];
    hex += kHex[digest[i] & 15];
  }
  return hex;
}

OutputFile DescribeOutput(const fs::path& dir, const std::string& relative) {
  const fs::path path = dir / relative;
  std::error_code ec;
  const auto size = fs::file_size(path, ec);
  if (ec) throw InternalError("output " + path.string() + " is missing: " + ec.message());
  return {relative, static_cast<std::int64_t>(size), FileSha256(path)};
}

std::string UtcNow() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buffer[32];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buffer;
}

json BuildVersions() {
  const BuildInfo& info = GetBuildInfo();
  json versions = {{"bespoke", info.version}};
  for (const auto& [name, version] : info.libraries) versions[name] = version;
  return versions;
}

json DoneRecord::ToJson() const {
  json j = {{"format", "bespoke-scan-done"},
            {"version", 1},
            {"status", status},
            {"scan_id", scan_id},
            {"input", input},
            {"input_size_bytes", input_size_bytes},
            {"input_sha256", input_sha256},
            {"results", results},
            {"steps", steps},
            {"time_s", time_s},
            {"versions", versions},
            {"settings", settings},
            {"finished_utc", finished_utc},
            {"worker", worker}};
  if (failure) {
    j["failure"] = {{"kind", failure->kind},
                    {"message", failure->message},
                    {"exit_code", failure->exit_code},
                    {"signal", failure->signal},
                    {"log_tail", failure->log_tail}};
  }
  json outs = json::array();
  for (const OutputFile& o : outputs) {
    outs.push_back({{"file", o.file}, {"size_bytes", o.size_bytes}, {"sha256", o.sha256}});
  }
  j["outputs"] = outs;
  return j;
}

DoneRecord DoneRecord::FromJson(const json& j, const std::string& what) {
  try {
    if (!j.is_object() || j.value("format", "") != "bespoke-scan-done") {
      throw InputError(what + ": not a bespoke done record");
    }
    DoneRecord r;
    r.status = j.at("status").get<std::string>();
    if (r.status != "ok" && r.status != "failed")
      throw InputError(what + ": unknown status " + r.status);
    r.scan_id = j.at("scan_id").get<std::string>();
    r.input = j.at("input").get<std::string>();
    r.input_size_bytes = j.value("input_size_bytes", std::int64_t{-1});
    r.input_sha256 = j.value("input_sha256", "");
    r.results = j.value("results", json::object());
    r.steps = j.value("steps", json::array());
    r.time_s = j.value("time_s", 0.0);
    r.versions = j.value("versions", json::object());
    r.settings = j.value("settings", json::object());
    r.finished_utc = j.value("finished_utc", "");
    r.worker = j.value("worker", json::object());
    if (j.contains("failure")) {
      const json& f = j.at("failure");
      r.failure =
          ScanFailure{f.at("kind").get<std::string>(), f.at("message").get<std::string>(),
                      f.value("exit_code", -1), f.value("signal", 0), f.value("log_tail", "")};
    }
    if (r.status == "failed" && !r.failure) throw InputError(what + ": failed without a reason");
    for (const json& o : j.at("outputs")) {
      r.outputs.push_back({o.at("file").get<std::string>(), o.at("size_bytes").get<std::int64_t>(),
                           o.at("sha256").get<std::string>()});
    }
    return r;
  } catch (const json::exception& e) {
    throw InputError(what + ": malformed done record: " + e.what());
  }
}

void WriteDoneRecord(const fs::path& dir, DoneRecord record) {
  if (record.finished_utc.empty()) record.finished_utc = UtcNow();
  WriteJsonFile(dir / kDoneFileName, record.ToJson());
}

std::optional<DoneRecord> ReadValidDoneRecord(const fs::path& dir, bool verify_hashes,
                                              std::string* problem) {
  auto fail = [&](const std::string& why) -> std::optional<DoneRecord> {
    if (problem) *problem = why;
    return std::nullopt;
  };
  const fs::path file = dir / kDoneFileName;
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) return fail("no done.json");
  DoneRecord record;
  try {
    record = DoneRecord::FromJson(ReadJsonFile(file), file.string());
  } catch (const InputError& e) {
    return fail(e.what());
  }
  for (const OutputFile& o : record.outputs) {
    const fs::path path = dir / o.file;
    const auto size = fs::file_size(path, ec);
    if (ec) return fail(o.file + ": missing");
    if (static_cast<std::int64_t>(size) != o.size_bytes) {
      return fail(o.file + ": " + std::to_string(size) + " bytes, recorded " +
                  std::to_string(o.size_bytes));
    }
    if (verify_hashes) {
      try {
        if (FileSha256(path) != o.sha256) return fail(o.file + ": SHA-256 differs from done.json");
      } catch (const InputError& e) {
        return fail(e.what());
      }
    }
  }
  return record;
}

}  // namespace bespoke

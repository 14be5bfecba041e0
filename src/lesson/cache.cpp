#include "lesson/cache.hpp"

#include <fstream>
#include <sstream>

#include "core/atomic_file.hpp"
#include "linkage/version.hpp"

namespace linkage::lesson {

namespace fs = std::filesystem;

ArtifactCache::ArtifactCache(fs::path folder, bool force) : folder_(std::move(folder)), force_(force) {}

fs::path ArtifactCache::record_path(const std::vector<std::string>& artifacts) const {
  return folder_ / ("." + artifacts.front() + ".cache.json");
}

std::optional<nlohmann::json> ArtifactCache::lookup(const std::vector<std::string>& artifacts,
                                                    const std::string& hash) const {
  if (force_ || artifacts.empty()) return std::nullopt;
  std::ifstream in(record_path(artifacts));
  if (!in) return std::nullopt;
  const nlohmann::json record = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (!record.is_object() || record.value("hash", "") != hash) return std::nullopt;
  const auto sizes = record.find("artifacts");
  if (sizes == record.end() || !sizes->is_object()) return std::nullopt;
  for (const std::string& name : artifacts) {
    std::error_code ec;
    const auto size = fs::file_size(folder_ / name, ec);
    const auto recorded = sizes->find(name);
    if (ec || recorded == sizes->end() || !recorded->is_number_unsigned() || recorded->get<std::uintmax_t>() != size)
      return std::nullopt;
  }
  return record.value("results", nlohmann::json::object());
}

void ArtifactCache::invalidate(const std::vector<std::string>& artifacts) const {
  if (artifacts.empty()) return;
  std::error_code ec;
  fs::remove(record_path(artifacts), ec);
}

void ArtifactCache::store(const std::vector<std::string>& artifacts, const std::string& hash,
                          const nlohmann::json& results) const {
  if (artifacts.empty()) return;
  nlohmann::json record;
  record["hash"] = hash;
  record["version"] = kVersion;
  nlohmann::json sizes = nlohmann::json::object();
  for (const std::string& name : artifacts) sizes[name] = fs::file_size(folder_ / name);
  record["artifacts"] = sizes;
  record["results"] = results;
  write_file_atomically(record_path(artifacts), record.dump(2) + "\n", "lesson cache");
}

}  // namespace linkage::lesson

#include "lesson/cache.hpp"

#include <fstream>
#include <sstream>

#include "core/atomic_file.hpp"
#include "linkage/version.hpp"

namespace linkage::lesson {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// Why a record cannot be used, or "" when its fields are all there with their types.
std::string record_problem(const json& record) {
  if (!record.is_object()) return "not a JSON object";
  const auto hash = record.find("hash");
  if (hash == record.end() || !hash->is_string()) return "no \"hash\" string";
  const auto sizes = record.find("artifacts");
  if (sizes == record.end() || !sizes->is_object()) return "no \"artifacts\" object";
  for (const auto& [name, size] : sizes->items())
    if (!size.is_number_unsigned()) return "the size of " + json(name).dump() + " is not a whole number";
  const auto results = record.find("results");
  if (results != record.end() && !results->is_object() && !results->is_null()) return "\"results\" is not an object";
  return "";
}

}  // namespace

ArtifactCache::ArtifactCache(fs::path folder, bool force, std::ostream& notes)
    : folder_(std::move(folder)), force_(force), notes_(&notes) {}

fs::path ArtifactCache::record_path(const std::vector<std::string>& artifacts) const {
  return folder_ / ("." + artifacts.front() + ".cache.json");
}

void ArtifactCache::note(const fs::path& record, const std::string& text) const {
  *notes_ << "linkage: note: cache record '" << record.string() << "' " << text << "\n";
  notes_->flush();
}

std::optional<json> ArtifactCache::lookup(const std::vector<std::string>& artifacts, const std::string& hash) const {
  if (force_ || artifacts.empty()) return std::nullopt;
  const fs::path path = record_path(artifacts);
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status)) return std::nullopt;       // never made, or invalidated
  if (fs::is_directory(status)) return std::nullopt;  // invalidate() deals with it
  const auto unreadable = [&](const std::string& why) -> std::optional<json> {
    note(path, "is unreadable (" + why + "); making it again");
    return std::nullopt;
  };
  std::ifstream in(path, std::ios::binary);
  if (!in) return unreadable("cannot open it");
  std::stringstream text;
  text << in.rdbuf();
  if (text.str().empty()) return unreadable("it is empty");
  json record;
  try {
    record = json::parse(text.str());
  } catch (const json::parse_error& e) {
    return unreadable("not JSON: a syntax error at byte " + std::to_string(e.byte));
  }
  if (const std::string problem = record_problem(record); !problem.empty()) return unreadable(problem);
  if (record["hash"].get<std::string>() != hash) return std::nullopt;  // the step changed
  const json& sizes = record["artifacts"];
  for (const std::string& name : artifacts) {
    const auto size = fs::file_size(folder_ / name, ec);
    const auto recorded = sizes.find(name);
    if (ec || recorded == sizes.end() || recorded->get<std::uintmax_t>() != size) return std::nullopt;
  }
  return record.value("results", json::object());
}

void ArtifactCache::invalidate(const std::vector<std::string>& artifacts) const {
  if (artifacts.empty()) return;
  const fs::path path = record_path(artifacts);
  std::error_code ec;
  if (!fs::is_directory(path, ec)) {
    fs::remove(path, ec);
    return;
  }
  // Nobody else uses this name, but a folder may hold someone's files: only an empty one goes.
  if (fs::remove(path, ec))
    note(path, "was an empty folder, not a file; removed it");
  else
    note(path, "is a folder with files in it, not a file; left it as it is, so this step is not cached");
}

void ArtifactCache::store(const std::vector<std::string>& artifacts, const std::string& hash,
                          const json& results) const {
  if (artifacts.empty()) return;
  std::error_code ec;
  if (fs::is_directory(record_path(artifacts), ec)) return;  // invalidate() said so
  json record;
  record["hash"] = hash;
  record["version"] = kVersion;
  json sizes = json::object();
  for (const std::string& name : artifacts) sizes[name] = fs::file_size(folder_ / name);
  record["artifacts"] = sizes;
  record["results"] = results;
  write_file_atomically(record_path(artifacts), record.dump(2) + "\n", "lesson cache");
}

}  // namespace linkage::lesson

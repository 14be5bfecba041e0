#pragma once
// Reusing what a step made last time. A step's outputs depend on its options, the
// inputs in effect, the quality and the program version; their content hash is stored
// in a record beside the step's first artifact (".NAME.cache.json") together with the
// results the step printed and the size of every artifact. The record is removed
// before a step writes and stored only after every artifact is complete, so a failed
// or interrupted step never counts as cached. A record that cannot be read (not JSON,
// wrong fields, a folder in its place) is a miss: one note says so and the step is made
// again.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace linkage::lesson {

class ArtifactCache {
 public:
  /// `force`: every lookup misses (but records are still written). Notes about unusable
  /// records go to `notes`, one line each.
  ArtifactCache(std::filesystem::path folder, bool force, std::ostream& notes);

  /// The stored results when the record matches `hash` and every artifact exists with
  /// the size recorded.
  [[nodiscard]] std::optional<nlohmann::json> lookup(const std::vector<std::string>& artifacts,
                                                     const std::string& hash) const;
  /// Forgets the step's record, before it writes its artifacts. A folder in the record's
  /// place is removed when empty, else left alone and the step goes unrecorded.
  void invalidate(const std::vector<std::string>& artifacts) const;
  /// Records the step once every artifact is written (unless a folder is in the way).
  void store(const std::vector<std::string>& artifacts, const std::string& hash, const nlohmann::json& results) const;

  /// The record's file for a step's artifacts.
  [[nodiscard]] std::filesystem::path record_path(const std::vector<std::string>& artifacts) const;

 private:
  void note(const std::filesystem::path& record, const std::string& text) const;

  std::filesystem::path folder_;
  bool force_;
  std::ostream* notes_;
};

}  // namespace linkage::lesson

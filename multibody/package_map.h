#pragma once

#include <map>
#include <string>
#include <vector>

namespace cairn::multibody {

/// Resolves the `package://<name>/<path>` URIs of URDF files to files on disk, from explicit entries
/// (name -> folder) and search paths (folders whose subfolders are packages), looked up in that order.
class PackageMap {
 public:
  /// Maps package `name` to `directory`; throws std::invalid_argument if the directory does not exist or the
  /// name is already mapped to another folder.
  void Add(const std::string& name, const std::string& directory);

  /// Adds "name=path" as produced by a command line flag; throws std::invalid_argument on another format.
  void AddSpec(const std::string& spec);

  /// Adds a folder whose subfolders are packages (a package `foo` is `directory/foo`).
  void AddSearchPath(const std::string& directory);

  /// The folder of package `name`; throws std::runtime_error naming the known packages if it is not found.
  std::string ResolvePackage(const std::string& name) const;

  /// True if ResolvePackage(name) would succeed.
  bool Contains(const std::string& name) const;

  /// Resolves a URDF file reference: `package://name/rest`, `file:///abs/path`, an absolute path, or a path
  /// relative to `base_directory` (the URDF's folder). The file is not required to exist.
  std::string ResolveUri(const std::string& uri, const std::string& base_directory) const;

  /// The explicit entries.
  const std::map<std::string, std::string>& packages() const { return packages_; }
  /// The search paths, in the order they were added.
  const std::vector<std::string>& search_paths() const { return search_paths_; }

 private:
  std::map<std::string, std::string> packages_;
  std::vector<std::string> search_paths_;
};

}  // namespace cairn::multibody

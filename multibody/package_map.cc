#include <cairn/multibody/package_map.h>

#include <filesystem>
#include <stdexcept>

#include <cairn/common/text_suggestions.h>

namespace cairn::multibody {

namespace fs = std::filesystem;

void PackageMap::Add(const std::string& name, const std::string& directory) {
  if (name.empty()) throw std::invalid_argument("PackageMap::Add: empty package name for folder '" + directory + "'");
  if (!fs::is_directory(directory)) {
    throw std::invalid_argument("package '" + name + "': folder '" + directory +
                                "' does not exist; give the package's root folder");
  }
  const std::string canonical = fs::canonical(directory).string();
  const auto it = packages_.find(name);
  if (it != packages_.end() && it->second != canonical) {
    throw std::invalid_argument("package '" + name + "' is already mapped to '" + it->second + "', not '" + canonical +
                                "'; map each package once");
  }
  packages_[name] = canonical;
}

void PackageMap::AddSpec(const std::string& spec) {
  const auto eq = spec.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == spec.size()) {
    throw std::invalid_argument("package mapping '" + spec +
                                "' is not of the form name=path (e.g. drchubo=/opt/drchubo)");
  }
  Add(spec.substr(0, eq), spec.substr(eq + 1));
}

void PackageMap::AddSearchPath(const std::string& directory) {
  if (!fs::is_directory(directory)) {
    throw std::invalid_argument("package search path '" + directory + "' is not a folder");
  }
  search_paths_.push_back(directory);
}

bool PackageMap::Contains(const std::string& name) const {
  if (packages_.count(name) > 0) return true;
  for (const std::string& dir : search_paths_) {
    if (fs::is_directory(fs::path(dir) / name)) return true;
  }
  return false;
}

std::string PackageMap::ResolvePackage(const std::string& name) const {
  const auto it = packages_.find(name);
  if (it != packages_.end()) return it->second;
  for (const std::string& dir : search_paths_) {
    const fs::path candidate = fs::path(dir) / name;
    if (fs::is_directory(candidate)) return candidate.string();
  }
  std::vector<std::string> known;
  for (const auto& entry : packages_) known.push_back(entry.first);
  for (const std::string& dir : search_paths_) {
    for (const auto& entry : fs::directory_iterator(dir)) {
      if (entry.is_directory()) known.push_back(entry.path().filename().string());
    }
  }
  std::string message = "package '" + name + "' is not known; map it with --package " + name +
                        "=<folder> (PackageMap::Add) or add a search path holding a '" + name + "' folder";
  if (!known.empty()) message += "; known packages closest to it: " + QuotedList(ClosestNames(name, known));
  throw std::runtime_error(message);
}

std::string PackageMap::ResolveUri(const std::string& uri, const std::string& base_directory) const {
  const std::string package_prefix = "package://";
  const std::string file_prefix = "file://";
  if (uri.compare(0, package_prefix.size(), package_prefix) == 0) {
    const std::string rest = uri.substr(package_prefix.size());
    const auto slash = rest.find('/');
    const std::string name = rest.substr(0, slash);
    const std::string path = slash == std::string::npos ? std::string() : rest.substr(slash + 1);
    return (fs::path(ResolvePackage(name)) / path).lexically_normal().string();
  }
  if (uri.compare(0, file_prefix.size(), file_prefix) == 0) return uri.substr(file_prefix.size());
  const fs::path path(uri);
  if (path.is_absolute()) return path.string();
  return (fs::path(base_directory) / path).lexically_normal().string();
}

}  // namespace cairn::multibody

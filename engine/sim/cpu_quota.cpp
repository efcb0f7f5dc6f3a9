#include "engine/sim/cpu_quota.h"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <vector>

namespace baize::engine {
namespace {

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(text);
  while (std::getline(in, part, separator)) parts.push_back(part);
  return parts;
}

// A whole non-negative number, or empty ("max", "-1", anything else).
std::optional<double> count(const std::string& text) {
  if (text.empty() ||
      !std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    return std::nullopt;
  }
  return std::stod(text);
}

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\n");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t\n") + 1 - first);
}

// Cores from a quota and a period of CPU time (both in us); empty unless both are positive counts.
std::optional<double> cores(const std::string& quota, const std::string& period) {
  const std::optional<double> q = count(trimmed(quota)), p = count(trimmed(period));
  if (!q || !p || *q <= 0 || *p <= 0) return std::nullopt;
  return *q / *p;
}

// Where a cgroup hierarchy is mounted: the mount point, and which cgroup its root is (inside a
// container the mount's root may lie below the hierarchy's).
struct Mount {
  std::string point, root;
};

// A mountinfo path field with the kernel's escapes (\040 for a space, \011, \012, \134) decoded.
std::string decodedField(const std::string& field) {
  std::string decoded;
  for (std::size_t i = 0; i < field.size(); ++i) {
    const bool escape = field[i] == '\\' && i + 3 < field.size() &&
                        std::all_of(field.begin() + i + 1, field.begin() + i + 4,
                                    [](char c) { return c >= '0' && c <= '7'; });
    if (escape) {
      decoded += static_cast<char>(std::stoi(field.substr(i + 1, 3), nullptr, 8));
      i += 3;
    } else {
      decoded += field[i];
    }
  }
  return decoded;
}

// The cgroup v2 mounts (fstype cgroup2) or the v1 mounts that carry the cpu controller.
std::vector<Mount> findMounts(const std::string& mountinfo, bool version2) {
  std::vector<Mount> mounts;
  for (const std::string& line : split(mountinfo, '\n')) {
    // "id parent major:minor root point options [optional fields] - fstype source superoptions"
    const std::vector<std::string> fields = split(line, ' ');
    const auto dash = std::find(fields.begin(), fields.end(), "-");
    if (fields.size() < 5 || dash == fields.end() || fields.end() - dash < 4) continue;
    const std::string& type = *(dash + 1);
    const bool matches = version2 ? type == "cgroup2" : type == "cgroup" && [&] {
      const std::vector<std::string> options = split(*(dash + 3), ',');
      return std::find(options.begin(), options.end(), "cpu") != options.end();
    }();
    if (matches) mounts.push_back({decodedField(fields[4]), decodedField(fields[3])});
  }
  return mounts;
}

// The part of cgroup `path` below `root` ("" for the root itself), or empty when it is not inside.
std::optional<std::string> below(const std::string& path, const std::string& root) {
  if (root == "/") return path == "/" ? std::string() : path;
  const bool inside = path.compare(0, root.size(), root) == 0 &&
                      (path.size() == root.size() || path[root.size()] == '/');
  if (!inside) return std::nullopt;
  return path.substr(root.size());
}

// This process's cgroup in the hierarchy: the v2 line "0::PATH", or the v1 line whose controllers
// include cpu.
std::optional<std::string> cgroupPath(const std::string& cgroup, bool version2) {
  for (const std::string& line : split(cgroup, '\n')) {
    const auto first = line.find(':'), second = line.find(':', first + 1);
    if (first == std::string::npos || second == std::string::npos) continue;
    const std::string controllers = line.substr(first + 1, second - first - 1);
    const std::vector<std::string> names = split(controllers, ',');
    const bool matches = version2 ? line.substr(0, first) == "0" && controllers.empty()
                                  : std::find(names.begin(), names.end(), "cpu") != names.end();
    if (matches) return line.substr(second + 1);
  }
  return std::nullopt;
}

// The smallest limit from the directory `relative` below the mount point up to the mount point.
std::optional<double> smallestLimit(
    const Mount& mount, const std::string& relative, bool version2,
    const std::function<std::optional<std::string>(const std::string&)>& read) {
  std::optional<double> smallest;
  std::string directory = mount.point + relative;
  while (true) {
    while (directory.size() > 1 && directory.back() == '/') directory.pop_back();
    std::optional<double> limit;
    if (version2) {
      // cpu.max: "QUOTA PERIOD", QUOTA "max" for none.
      if (const std::optional<std::string> text = read(directory + "/cpu.max")) {
        const std::vector<std::string> words = split(trimmed(*text), ' ');
        if (words.size() == 2) limit = cores(words[0], words[1]);
      }
    } else {
      // cpu.cfs_quota_us is -1 for none.
      const std::optional<std::string> quota = read(directory + "/cpu.cfs_quota_us");
      const std::optional<std::string> period = read(directory + "/cpu.cfs_period_us");
      if (quota && period) limit = cores(*quota, *period);
    }
    if (limit) smallest = smallest ? std::min(*smallest, *limit) : *limit;
    if (directory.size() <= mount.point.size()) break;
    directory = directory.substr(0, directory.rfind('/'));
    if (directory.size() < mount.point.size()) break;
  }
  return smallest;
}

// The limit one hierarchy sets: read through the mount whose root holds the process's cgroup most
// closely (the longest root that contains it); if none holds it (a namespace that names cgroups
// from elsewhere), the first mount's own directory, which a container's limit is set on.
std::optional<double> hierarchyLimit(
    const std::string& mountinfo, const std::string& cgroup, bool version2,
    const std::function<std::optional<std::string>(const std::string&)>& read) {
  const std::vector<Mount> mounts = findMounts(mountinfo, version2);
  const std::optional<std::string> path = cgroupPath(cgroup, version2);
  if (mounts.empty() || !path) return std::nullopt;
  const Mount* best = nullptr;
  std::string relative;
  for (const Mount& mount : mounts) {
    const std::optional<std::string> inside = below(*path, mount.root);
    if (inside && (!best || mount.root.size() > best->root.size())) {
      best = &mount;
      relative = *inside;
    }
  }
  if (!best) return smallestLimit(mounts.front(), "", version2, read);
  return smallestLimit(*best, relative, version2, read);
}

std::optional<std::string> readFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

std::optional<double> cgroupCpuLimitCores(
    const std::string& mountinfo, const std::string& cgroup,
    const std::function<std::optional<std::string>(const std::string& path)>& read) {
  std::optional<double> smallest;
  for (const bool version2 : {false, true}) {
    if (const std::optional<double> limit = hierarchyLimit(mountinfo, cgroup, version2, read))
      smallest = smallest ? std::min(*smallest, *limit) : *limit;
  }
  return smallest;
}

std::optional<double> cgroupCpuLimitCores() {
  const std::optional<std::string> mountinfo = readFile("/proc/self/mountinfo");
  const std::optional<std::string> cgroup = readFile("/proc/self/cgroup");
  if (!mountinfo || !cgroup) return std::nullopt;
  return cgroupCpuLimitCores(*mountinfo, *cgroup, readFile);
}

bool twoCoresAllowed(int cores_in_affinity_mask, std::optional<double> cgroup_limit_cores) {
  return cores_in_affinity_mask >= 2 && (!cgroup_limit_cores || *cgroup_limit_cores >= 2);
}

}  // namespace baize::engine

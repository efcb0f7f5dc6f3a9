#include "engine/cpu_quota.h"

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
  if (text.empty() || !std::all_of(text.begin(), text.end(), [](char c) {
        return c >= '0' && c <= '9';
      })) {
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

// The cgroup v2 mount (fstype cgroup2) or the v1 mount that carries the cpu controller.
std::optional<Mount> findMount(const std::string& mountinfo, bool version2) {
  for (const std::string& line : split(mountinfo, '\n')) {
    // "id parent major:minor root point options [optional fields] - fstype source superoptions"
    const std::vector<std::string> fields = split(line, ' ');
    const auto dash = std::find(fields.begin(), fields.end(), "-");
    if (fields.size() < 5 || dash == fields.end() || fields.end() - dash < 4) continue;
    const std::string& type = *(dash + 1);
    const bool matches =
        version2 ? type == "cgroup2"
                 : type == "cgroup" && [&] {
                     const std::vector<std::string> options = split(*(dash + 3), ',');
                     return std::find(options.begin(), options.end(), "cpu") != options.end();
                   }();
    if (matches) return Mount{fields[4], fields[3]};
  }
  return std::nullopt;
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

// The smallest limit from the cgroup's directory up to the mount point.
std::optional<double> smallestLimit(
    const Mount& mount, const std::string& path, bool version2,
    const std::function<std::optional<std::string>(const std::string&)>& read) {
  // The part of the path below the mount's root (the whole path when the root is "/").
  std::string below = path;
  if (mount.root != "/") {
    const bool inside = path.compare(0, mount.root.size(), mount.root) == 0 &&
                        (path.size() == mount.root.size() || path[mount.root.size()] == '/');
    if (!inside) return std::nullopt;
    below = path.substr(mount.root.size());
  }
  std::optional<double> smallest;
  std::string directory = mount.point + below;
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
    const std::optional<Mount> mount = findMount(mountinfo, version2);
    const std::optional<std::string> path = cgroupPath(cgroup, version2);
    if (!mount || !path) continue;
    if (const std::optional<double> limit = smallestLimit(*mount, *path, version2, read))
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

}  // namespace baize::engine

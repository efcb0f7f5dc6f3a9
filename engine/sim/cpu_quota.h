// The CPU time a Linux control group (cgroup) lets this process use, in cores: a container started
// with a CPU limit (docker --cpus=1) sees every core of its machine in its affinity mask, but may
// use only the limit's worth of CPU time, and a thread that spins on a second core spends the
// first's share. A worker that solves cushion impacts ahead (cushion_impact_worker.h) is worth
// handing over only where two cores' worth is allowed.
#pragma once

#include <functional>
#include <optional>
#include <string>

namespace baize::engine {

// The CPU limit of this process's cgroup and of the cgroups above it as far as the cgroup mount
// shows them (the smallest), in cores, from the cgroup v1 cpu controller and cgroup v2 (the
// smaller); empty when none limits it or none can be read (not Linux, no cgroup file system
// mounted). A limit set above a container's cgroup namespace is not visible from inside it.
std::optional<double> cgroupCpuLimitCores();

// The same from the files' contents, for tests: `mountinfo` as /proc/self/mountinfo, `cgroup` as
// /proc/self/cgroup, and `read` returning a file's contents (empty if it cannot be read).
std::optional<double> cgroupCpuLimitCores(
    const std::string& mountinfo, const std::string& cgroup,
    const std::function<std::optional<std::string>(const std::string& path)>& read);

// Whether a second thread may run beside the caller: two or more cores in its affinity mask, and a
// cgroup CPU limit, if any, of two cores or more (under a smaller one a spinning worker would
// spend the caller's CPU time).
bool twoCoresAllowed(int cores_in_affinity_mask, std::optional<double> cgroup_limit_cores);

}  // namespace baize::engine

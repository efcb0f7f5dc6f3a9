#include "engine/cpu_quota.h"

#include <gtest/gtest.h>

#include <map>

namespace baize::engine {
namespace {

// A file system of a few files: a path not in it cannot be read.
struct FakeFiles {
  std::map<std::string, std::string> files;
  std::optional<std::string> operator()(const std::string& path) const {
    const auto found = files.find(path);
    if (found == files.end()) return std::nullopt;
    return found->second;
  }
};

// A host with cgroup v1 controllers and an empty v2 hierarchy beside them, as many machines have.
const char* kHybridMountinfo =
    "31 23 0:28 / /sys/fs/cgroup rw,relatime - tmpfs tmpfs rw,mode=755\n"
    "32 31 0:29 / /sys/fs/cgroup/cpu,cpuacct rw,relatime shared:9 - cgroup cgroup rw,cpu,cpuacct\n"
    "34 31 0:31 / /sys/fs/cgroup/cpuset rw,relatime - cgroup cgroup rw,cpuset\n"
    "40 31 0:37 / /sys/fs/cgroup/systemd rw,relatime - cgroup cgroup rw,name=systemd\n"
    "41 31 0:38 / /sys/fs/cgroup/unified rw,relatime - cgroup2 cgroup2 rw\n";
const char* kHybridCgroup =
    "4:cpu,cpuacct:/user.slice/job\n"
    "3:cpuset:/\n"
    "1:name=systemd:/user.slice/job\n"
    "0::/user.slice/job\n";

// A container on cgroup v2, its own cgroup namespace: its cgroup is the mount's root.
const char* kV2Mountinfo = "600 500 0:40 / /sys/fs/cgroup rw,nosuid - cgroup2 cgroup2 rw\n";
const char* kV2Cgroup = "0::/\n";

TEST(CgroupCpuLimit, NoneWhenNoCgroupSetsOne) {
  FakeFiles fs{{{"/sys/fs/cgroup/cpu,cpuacct/user.slice/job/cpu.cfs_quota_us", "-1\n"},
                {"/sys/fs/cgroup/cpu,cpuacct/user.slice/job/cpu.cfs_period_us", "100000\n"},
                {"/sys/fs/cgroup/cpu,cpuacct/cpu.cfs_quota_us", "-1\n"},
                {"/sys/fs/cgroup/cpu,cpuacct/cpu.cfs_period_us", "100000\n"}}};
  EXPECT_FALSE(cgroupCpuLimitCores(kHybridMountinfo, kHybridCgroup, fs).has_value());
  FakeFiles v2{{{"/sys/fs/cgroup/cpu.max", "max 100000\n"}}};
  EXPECT_FALSE(cgroupCpuLimitCores(kV2Mountinfo, kV2Cgroup, v2).has_value());
}

TEST(CgroupCpuLimit, ReadsAVersion1QuotaOfTheProcesssCgroup) {
  FakeFiles fs{{{"/sys/fs/cgroup/cpu,cpuacct/user.slice/job/cpu.cfs_quota_us", "150000\n"},
                {"/sys/fs/cgroup/cpu,cpuacct/user.slice/job/cpu.cfs_period_us", "100000\n"}}};
  EXPECT_EQ(cgroupCpuLimitCores(kHybridMountinfo, kHybridCgroup, fs), 1.5);
}

TEST(CgroupCpuLimit, TakesTheSmallestLimitOfTheCgroupAndThoseAboveIt) {
  FakeFiles fs{{{"/sys/fs/cgroup/cpu,cpuacct/user.slice/job/cpu.cfs_quota_us", "400000\n"},
                {"/sys/fs/cgroup/cpu,cpuacct/user.slice/job/cpu.cfs_period_us", "100000\n"},
                {"/sys/fs/cgroup/cpu,cpuacct/user.slice/cpu.cfs_quota_us", "50000\n"},
                {"/sys/fs/cgroup/cpu,cpuacct/user.slice/cpu.cfs_period_us", "100000\n"},
                {"/sys/fs/cgroup/cpu,cpuacct/cpu.cfs_quota_us", "-1\n"},
                {"/sys/fs/cgroup/cpu,cpuacct/cpu.cfs_period_us", "100000\n"}}};
  EXPECT_EQ(cgroupCpuLimitCores(kHybridMountinfo, kHybridCgroup, fs), 0.5);
  // Nothing outside the mount is read: a limit above the mount point does not count.
  fs.files["/sys/fs/cgroup/cpu.cfs_quota_us"] = "10000\n";
  fs.files["/sys/fs/cgroup/cpu.cfs_period_us"] = "100000\n";
  EXPECT_EQ(cgroupCpuLimitCores(kHybridMountinfo, kHybridCgroup, fs), 0.5);
}

TEST(CgroupCpuLimit, ReadsAVersion2Limit) {
  FakeFiles fs{{{"/sys/fs/cgroup/cpu.max", "100000 100000\n"}}};
  EXPECT_EQ(cgroupCpuLimitCores(kV2Mountinfo, kV2Cgroup, fs), 1.0);
  // A nested cgroup under a mount whose root is the host's path to the container.
  const std::string nested_mountinfo =
      "600 500 0:40 /machine/ctr /sys/fs/cgroup rw,nosuid - cgroup2 cgroup2 rw\n";
  FakeFiles nested{{{"/sys/fs/cgroup/app/cpu.max", "250000 100000\n"},
                    {"/sys/fs/cgroup/cpu.max", "300000 100000\n"}}};
  EXPECT_EQ(cgroupCpuLimitCores(nested_mountinfo, "0::/machine/ctr/app\n", nested), 2.5);
  // A cgroup outside the mount's root (a sibling whose name merely starts the same) is not read.
  EXPECT_FALSE(cgroupCpuLimitCores(nested_mountinfo, "0::/machine/ctr2/app\n", nested).has_value());
}

TEST(CgroupCpuLimit, IgnoresWhatItCannotRead) {
  FakeFiles garbled{{{"/sys/fs/cgroup/cpu.max", "lots 100000\n"}}};
  EXPECT_FALSE(cgroupCpuLimitCores(kV2Mountinfo, kV2Cgroup, garbled).has_value());
  FakeFiles zero_period{{{"/sys/fs/cgroup/cpu.max", "100000 0\n"}}};
  EXPECT_FALSE(cgroupCpuLimitCores(kV2Mountinfo, kV2Cgroup, zero_period).has_value());
  FakeFiles fs{{{"/sys/fs/cgroup/cpu.max", "100000 100000\n"}}};
  EXPECT_FALSE(cgroupCpuLimitCores("", kV2Cgroup, fs).has_value());  // no cgroup mount
  EXPECT_FALSE(cgroupCpuLimitCores(kV2Mountinfo, "", fs).has_value());  // no cgroup of ours
  EXPECT_FALSE(cgroupCpuLimitCores("not a mountinfo line\n - \n", "::\n", fs).has_value());
}

}  // namespace
}  // namespace baize::engine

#include "engine/sim/cpu_quota.h"

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

TEST(CgroupCpuLimit, ReadsAVersion1QuotaOfTheProcessCgroup) {
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
  // A cgroup outside the mount's root (a sibling whose name merely starts the same): its own
  // directory is not looked for under the mount; the mount's own limit counts.
  nested.files["/sys/fs/cgroup/2/app/cpu.max"] = "50000 100000\n";
  EXPECT_EQ(cgroupCpuLimitCores(nested_mountinfo, "0::/machine/ctr2/app\n", nested), 3.0);
}

TEST(CgroupCpuLimit, ReadsAVersion1ContainerWhoseMountRootIsItsCgroup) {
  // Docker on cgroup v1 without a cgroup namespace: the mount shows the container's cgroup.
  const std::string mountinfo =
      "700 600 0:29 /docker/abc /sys/fs/cgroup/cpu,cpuacct ro,nosuid - cgroup cgroup "
      "rw,cpuacct,cpu\n";
  FakeFiles fs{{{"/sys/fs/cgroup/cpu,cpuacct/cpu.cfs_quota_us", "200000\n"},
                {"/sys/fs/cgroup/cpu,cpuacct/cpu.cfs_period_us", "100000\n"}}};
  EXPECT_EQ(cgroupCpuLimitCores(mountinfo, "5:cpuacct,cpu:/docker/abc\n", fs), 2.0);
}

TEST(CgroupCpuLimit, TakesTheSmallerOfVersion1AndVersion2) {
  const std::string mountinfo = std::string(kHybridMountinfo);
  FakeFiles fs{{{"/sys/fs/cgroup/cpu,cpuacct/user.slice/job/cpu.cfs_quota_us", "300000\n"},
                {"/sys/fs/cgroup/cpu,cpuacct/user.slice/job/cpu.cfs_period_us", "100000\n"},
                {"/sys/fs/cgroup/unified/user.slice/job/cpu.max", "120000 100000\n"}}};
  EXPECT_EQ(cgroupCpuLimitCores(mountinfo, kHybridCgroup, fs), 1.2);
}

TEST(CgroupCpuLimit, UsesTheMountThatHoldsTheCgroup) {
  // The hierarchy mounted twice: first with a root elsewhere, then whole.
  const std::string mountinfo =
      "600 500 0:40 /elsewhere /mnt/other rw - cgroup2 cgroup2 rw\n"
      "601 500 0:40 / /sys/fs/cgroup rw - cgroup2 cgroup2 rw\n";
  FakeFiles fs{{{"/sys/fs/cgroup/job/cpu.max", "100000 100000\n"},
                {"/mnt/other/cpu.max", "400000 100000\n"}}};
  EXPECT_EQ(cgroupCpuLimitCores(mountinfo, "0::/job\n", fs), 1.0);
}

TEST(CgroupCpuLimit, DecodesEscapedPathsInMountinfo) {
  // The kernel writes a space in a mountinfo path as \040; /proc/self/cgroup writes it as is.
  const std::string mountinfo =
      "600 500 0:40 /machine/my\\040ctr /sys/fs/my\\040cgroup rw - cgroup2 cgroup2 rw\n";
  FakeFiles fs{{{"/sys/fs/my cgroup/app/cpu.max", "150000 100000\n"}}};
  EXPECT_EQ(cgroupCpuLimitCores(mountinfo, "0::/machine/my ctr/app\n", fs), 1.5);
}

TEST(TwoCoresAllowed, NeedsTwoCoresInTheMaskAndALimitOfTwoOrNone) {
  EXPECT_TRUE(twoCoresAllowed(2, std::nullopt));
  EXPECT_TRUE(twoCoresAllowed(8, 2.0));
  EXPECT_FALSE(twoCoresAllowed(8, 1.5));
  EXPECT_FALSE(twoCoresAllowed(1, std::nullopt));
  EXPECT_FALSE(twoCoresAllowed(1, 4.0));
  EXPECT_FALSE(twoCoresAllowed(0, std::nullopt));  // the count unknown
}

TEST(CgroupCpuLimit, IgnoresWhatItCannotRead) {
  FakeFiles garbled{{{"/sys/fs/cgroup/cpu.max", "lots 100000\n"}}};
  EXPECT_FALSE(cgroupCpuLimitCores(kV2Mountinfo, kV2Cgroup, garbled).has_value());
  FakeFiles zero_period{{{"/sys/fs/cgroup/cpu.max", "100000 0\n"}}};
  EXPECT_FALSE(cgroupCpuLimitCores(kV2Mountinfo, kV2Cgroup, zero_period).has_value());
  FakeFiles fs{{{"/sys/fs/cgroup/cpu.max", "100000 100000\n"}}};
  EXPECT_FALSE(cgroupCpuLimitCores("", kV2Cgroup, fs).has_value());     // no cgroup mount
  EXPECT_FALSE(cgroupCpuLimitCores(kV2Mountinfo, "", fs).has_value());  // no cgroup of ours
  EXPECT_FALSE(cgroupCpuLimitCores("not a mountinfo line\n - \n", "::\n", fs).has_value());
}

}  // namespace
}  // namespace baize::engine

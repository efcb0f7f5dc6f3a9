#include "tools/baize/cushion_sweep.h"

#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <system_error>

#include "physics/value_text.h"
#include "tools/baize/atomic_file.h"

namespace baize::tools {
namespace {

constexpr double kFirstAngleDeg = 1;
constexpr double kLastAngleDeg = 179;
constexpr double kAngleStepDeg = 1;
constexpr double kDegreesPerRadian = 180.0 / 3.14159265358979323846;

// One figure of rebound curves: each curve is a shot whose angle the sweep varies.
struct CurveFamily {
  const char* file_name;
  std::vector<CushionShot> curves;
};

std::vector<CurveFamily> reboundFamilies() {
  const auto shot = [](double speed_mps, double topspin_k, double sidespin_k) {
    CushionShot s;
    s.speed_mps = speed_mps;
    s.topspin_k = topspin_k;
    s.sidespin_k = sidespin_k;
    return s;
  };
  return {
      {"fig6.csv",
       {shot(0.5, 1, 0), shot(1.0, 1, 0), shot(1.5, 1, 0), shot(2.0, 1, 0), shot(2.5, 1, 0)}},
      {"fig7.csv", {shot(1, -1, 0), shot(1, 0, 0), shot(1, 1, 0), shot(1, 2, 0), shot(1, 3, 0)}},
      {"fig8.csv", {shot(1, 1, -2), shot(1, 1, -1), shot(1, 1, 0), shot(1, 1, 1), shot(1, 1, 2)}},
  };
}

void writeReboundFamily(AtomicFile& file, const CurveFamily& family,
                        const physics::CushionParams& params, const SolverSetting& setting) {
  std::ostream& out = file.stream();
  out << "speed_mps,topspin_k,sidespin_k,alpha_deg,"
         "rebound_speed_mps,rebound_angle_deg,speed_ratio\n";
  const int angle_count =
      static_cast<int>(std::lround((kLastAngleDeg - kFirstAngleDeg) / kAngleStepDeg)) + 1;
  for (CushionShot shot : family.curves) {
    for (int i = 0; i < angle_count; ++i) {
      shot.angle_deg = kFirstAngleDeg + i * kAngleStepDeg;
      const physics::BallVelocity incoming = incomingBallOf(shot, params.radius_m);
      const Rebound rebound = reboundOf(solveCushionShot(params, incoming, setting).after);
      out << physics::valueText(shot.speed_mps) << ',' << physics::valueText(shot.topspin_k) << ','
          << physics::valueText(shot.sidespin_k) << ',' << physics::valueText(shot.angle_deg) << ','
          << physics::valueText(rebound.speed_mps) << ',' << physics::valueText(rebound.angle_deg)
          << ',' << physics::valueText(rebound.speed_mps / shot.speed_mps) << '\n';
    }
  }
}

// Fig. 10: s and Phi at the cushion contact I, s' and Phi' at the cloth contact C. Where a slip
// speed is zero (the contact sticks) atan2 gives 0 or noise: its direction has no meaning there.
void writeSlipCurves(AtomicFile& file, const physics::CushionParams& params,
                     const SolverSetting& setting) {
  CushionShot shot;
  shot.speed_mps = 2;
  shot.angle_deg = 45;
  shot.topspin_k = 1.5;
  shot.sidespin_k = 2;
  const physics::BallVelocity incoming = incomingBallOf(shot, params.radius_m);
  const physics::CushionImpactResult result =
      solveCushionShot(params, incoming, setting, /*record_trace=*/true);
  std::ostream& out = file.stream();
  out << "impulse_Ns,cushion_slip_mps,cushion_slip_angle_deg,cloth_slip_mps,cloth_slip_angle_deg\n";
  for (const physics::ImpactSample& sample : result.trace) {
    const Eigen::Vector2d& s = sample.cushion_slip;
    const Eigen::Vector2d& c = sample.cloth_slip;
    out << physics::valueText(sample.impulse_Ns) << ',' << physics::valueText(s.norm()) << ','
        << physics::valueText(std::atan2(s.y(), s.x()) * kDegreesPerRadian) << ','
        << physics::valueText(c.norm()) << ','
        << physics::valueText(std::atan2(c.y(), c.x()) * kDegreesPerRadian) << '\n';
  }
}

}  // namespace

std::vector<std::string> writeCushionSweep(const std::string& directory,
                                           const physics::CushionParams& params,
                                           const SolverSetting& setting) {
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) {
    throw std::runtime_error("--sweep = " + directory +
                             ": cannot create the directory: " + error.message());
  }
  const auto pathOf = [&](const char* name) {
    return (std::filesystem::path(directory) / name).string();
  };
  std::vector<std::string> written;
  for (const CurveFamily& family : reboundFamilies()) {
    AtomicFile file(pathOf(family.file_name), "--sweep");
    writeReboundFamily(file, family, params, setting);
    file.commit();
    written.push_back(pathOf(family.file_name));
  }
  AtomicFile slips(pathOf("fig10.csv"), "--sweep");
  writeSlipCurves(slips, params, setting);
  slips.commit();
  written.push_back(pathOf("fig10.csv"));
  return written;
}

}  // namespace baize::tools

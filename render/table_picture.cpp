#include "render/table_picture.h"

#include <cmath>

#include "render/polygon_triangulation.h"

namespace baize::render {
namespace {

// Points per jaw arc: the arcs are 4 mm in radius, so 8 points are far below a pixel apart.
constexpr int kJawArcPoints = 8;
// Sizes of markings, m.
constexpr double kDiamondRadius_m = 0.007;
constexpr double kSpotRadius_m = 0.005;
constexpr double kLineWidth_m = 0.003;
// Points along the D's half circle: 2 degrees apart.
constexpr int kDArcPoints = 91;

Mesh rectangle(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, const Rgba& colour) {
  const Eigen::Vector2d a = lo, b(hi.x(), lo.y()), c = hi, d(lo.x(), hi.y());
  return Mesh{{a, b, c, a, c, d}, 0.0, colour};
}

// The band between two centred rectangles, as four rectangles (drawing a band rather than a full
// rectangle under the cloth saves filling most of the image twice).
Mesh frame(const Eigen::Vector2d& inner_half, const Eigen::Vector2d& outer_half, double z_m,
           const Rgba& colour) {
  Mesh band{{}, z_m, colour};
  const auto add = [&](const Mesh& piece) {
    band.triangles_m.insert(band.triangles_m.end(), piece.triangles_m.begin(),
                            piece.triangles_m.end());
  };
  const Eigen::Vector2d o = outer_half, i = inner_half;
  add(rectangle({-o.x(), -o.y()}, {o.x(), -i.y()}, colour));  // bottom, full length
  add(rectangle({-o.x(), i.y()}, {o.x(), o.y()}, colour));    // top, full length
  add(rectangle({-o.x(), -i.y()}, {-i.x(), i.y()}, colour));  // left, between them
  add(rectangle({i.x(), -i.y()}, {o.x(), i.y()}, colour));    // right
  return band;
}

Disc flatDisc(const Eigen::Vector2d& centre, double radius, const Rgba& colour) {
  return Disc{Eigen::Vector3d(centre.x(), centre.y(), 0), radius, colour, DiscStyle::Flat, 0, {}};
}

// Appends `piece` to `outline`, reversed when its far end is nearer the outline's last point.
void appendOriented(std::vector<Eigen::Vector2d> piece, std::vector<Eigen::Vector2d>& outline) {
  if (!outline.empty() &&
      (piece.back() - outline.back()).norm() < (piece.front() - outline.back()).norm()) {
    std::reverse(piece.begin(), piece.end());
  }
  for (const Eigen::Vector2d& p : piece) {
    if (outline.empty() || (p - outline.back()).norm() > 0) outline.push_back(p);
  }
}

std::vector<Eigen::Vector2d> arcPoints(const engine::JawArc& arc) {
  std::vector<Eigen::Vector2d> points;
  for (int i = 0; i < kJawArcPoints; ++i) {
    const double f = static_cast<double>(i) / (kJawArcPoints - 1);
    points.push_back(
        arc.pointAt(arc.start_angle_rad + f * (arc.end_angle_rad - arc.start_angle_rad)));
  }
  return points;
}

}  // namespace

TableColours tableColours(engine::TableKind kind) {
  if (kind == engine::TableKind::Snooker) {
    return {colourFromHex("#1f6b35"), colourFromHex("#174f27"), colourFromHex("#4a2a14"),
            colourFromHex("#0a0a0a"), colourFromHex("#e8e8e0"), colourFromHex("#103a1c"),
            colourFromHex("#2e1a0c")};
  }
  return {colourFromHex("#1c6fa8"), colourFromHex("#15557f"), colourFromHex("#4a2a14"),
          colourFromHex("#0a0a0a"), colourFromHex("#e8e8e0"), colourFromHex("#0f3d5c"),
          colourFromHex("#2e1a0c")};
}

std::vector<Eigen::Vector2d> clothOutline(const engine::Table& table) {
  // Per pocket k (table.h): cushions 3k (entry facing), 3k+1 (exit facing), 3k+2 (rail to pocket
  // k+1); jaw arcs 2k (entry), 2k+1 (exit). Counterclockwise: entry facing, across the pocket, exit
  // facing, exit jaw, rail, the next pocket's entry jaw.
  std::vector<Eigen::Vector2d> outline;
  const std::size_t pockets = table.pockets.size();
  for (std::size_t k = 0; k < pockets; ++k) {
    const engine::CushionSegment& entry = table.cushions.at(3 * k);
    const engine::CushionSegment& exit = table.cushions.at(3 * k + 1);
    const engine::CushionSegment& rail = table.cushions.at(3 * k + 2);
    appendOriented({entry.start_m, entry.end_m}, outline);
    appendOriented({exit.start_m, exit.end_m}, outline);
    appendOriented(arcPoints(table.jaw_arcs.at(2 * k + 1)), outline);
    appendOriented({rail.start_m, rail.end_m}, outline);
    appendOriented(arcPoints(table.jaw_arcs.at(2 * ((k + 1) % pockets))), outline);
  }
  if (outline.size() > 1 && outline.front() == outline.back()) outline.pop_back();
  return outline;
}

void addTable(const engine::Table& table, Picture& picture) {
  const TableColours colours = tableColours(table.kind);
  const Eigen::Vector2d half(table.length_m / 2, table.width_m / 2);
  const Eigen::Vector2d rail_edge = half + Eigen::Vector2d::Constant(kRailOuterEdge_m);
  const Eigen::Vector2d cushion_edge = half + Eigen::Vector2d::Constant(kCushionWidth_m);
  picture.min_corner_m = -rail_edge;
  picture.max_corner_m = rail_edge;
  picture.lowest_m = -kTableSideDepth_m;
  const double top_m = table.cushion_contact_height_m;  // of the rail and the cushions

  // The cloth covers everything inside the cushion noses (its outline only reaches further out,
  // into the pockets), so the rail and the cushion are bands around it.
  // The near side of the table (towards the angled view's camera).
  picture.items.push_back(Wall{{-rail_edge.x(), -rail_edge.y()},
                               {rail_edge.x(), -rail_edge.y()},
                               -kTableSideDepth_m,
                               top_m,
                               colours.table_side});
  picture.items.push_back(frame(cushion_edge, rail_edge, top_m, colours.rail));
  picture.items.push_back(frame(half, cushion_edge, top_m, colours.cushion));
  for (std::size_t k = 0; k < table.pockets.size(); ++k) {
    const engine::CushionSegment& rail = table.cushions.at(3 * k + 2);
    if (rail.inward_normal.y() > 0.5) {
      // A near rail cushion: its top again in front of everything; its nose faces away.
      const Eigen::Vector2d back = -kCushionWidth_m * rail.inward_normal;
      picture.foreground.push_back(Mesh{{rail.start_m, rail.end_m, rail.end_m + back, rail.start_m,
                                         rail.end_m + back, rail.start_m + back},
                                        top_m,
                                        colours.cushion});
    } else {
      picture.items.push_back(Wall{rail.start_m, rail.end_m, 0.0, top_m, colours.cushion_face});
    }
  }
  for (const engine::Pocket& pocket : table.pockets) {
    const engine::PocketSpec& spec =
        pocket.kind == engine::PocketKind::Corner ? table.corner_pocket : table.side_pocket;
    // The hole: wide enough to reach the mouth, its back edge where the capture circle's is.
    const double hole_radius_m = std::max(pocket.capture.radius_m, 0.5 * spec.mouth_width_m);
    Disc hole = flatDisc(pocket.capture.centre_m, hole_radius_m, colours.pocket);
    hole.centre_m.z() = top_m;  // a hole in the rail's top
    picture.items.push_back(hole);
  }
  picture.items.push_back(Mesh{triangulate(clothOutline(table)), 0.0, colours.cloth});

  if (table.pool_markings) {
    const engine::PoolMarkings& m = *table.pool_markings;
    for (const Eigen::Vector2d& d : m.diamonds_m) {
      Disc diamond = flatDisc(d, kDiamondRadius_m, colours.marking);
      diamond.centre_m.z() = top_m;  // on the rail's top
      picture.items.push_back(diamond);
    }
    picture.items.push_back(flatDisc(m.foot_spot_m, kSpotRadius_m, colours.marking));
    picture.items.push_back(flatDisc(m.head_spot_m, kSpotRadius_m, colours.marking));
  }
  if (table.snooker_markings) {
    const engine::SnookerMarkings& m = *table.snooker_markings;
    picture.items.push_back(Stroke{
        {Eigen::Vector2d(m.baulk_line_x_m, -half.y()), Eigen::Vector2d(m.baulk_line_x_m, half.y())},
        kLineWidth_m,
        0.0,
        colours.marking});
    Stroke d{{}, kLineWidth_m, 0.0, colours.marking};
    for (int i = 0; i < kDArcPoints; ++i) {  // the half towards the bottom cushion (-x)
      const double angle = M_PI / 2 + M_PI * i / (kDArcPoints - 1);
      d.points_m.push_back(m.brown_spot_m +
                           m.d_radius_m * Eigen::Vector2d(std::cos(angle), std::sin(angle)));
    }
    picture.items.push_back(d);
    for (const Eigen::Vector2d& spot : {m.yellow_spot_m, m.green_spot_m, m.brown_spot_m,
                                        m.blue_spot_m, m.pink_spot_m, m.black_spot_m}) {
      picture.items.push_back(flatDisc(spot, kSpotRadius_m, colours.marking));
    }
  }
}

}  // namespace baize::render

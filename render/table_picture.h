// A table as a player sees it from above, as draw items (render/draw_items.h): the wooden rail,
// the cushion rubber, the pocket holes, the cloth bounded by the real cushion outline (rails,
// jaws and facings from engine/io/table.h), diamonds and spots on pool tables, the baulk line, the
// D and the spots on snooker tables.
#pragma once

#include <vector>

#include "engine/io/table.h"
#include "render/draw_items.h"

namespace baize::render {

// Widths beyond the cushion nose, m: the cushion rubber, then the wooden rail up to the outer edge
// (wide enough to hold the diamonds, which sit about 0.09 m behind the nose).
constexpr double kCushionWidth_m = 0.05;
constexpr double kRailOuterEdge_m = 0.15;
// How far the table's side shows below the cloth in the angled view, m.
constexpr double kTableSideDepth_m = 0.12;

// Colours of the table (not of the balls, which the ball set gives).
struct TableColours {
  Rgba cloth, cushion, rail, pocket, marking;
  Rgba cushion_face, table_side;  // the vertical faces, darker: lit from above
};
TableColours tableColours(engine::TableKind kind);

// The closed cushion outline around the cloth, counterclockwise: rails, jaw arcs (sampled),
// facings, and across each pocket from one facing's end to the other's.
std::vector<Eigen::Vector2d> clothOutline(const engine::Table& table);

// Appends the table's items to `picture` (bottom layers first) and sets its frame to the rail's
// outer edge. The rail and the cushions stand at the cushion contact height, the cloth at 0: in the
// angled view (from the -y side) the near side of the table, the far and end cushions' noses show,
// and the near cushions go to the picture's foreground (they hide the cloth behind them). Seen from
// straight above all of this draws as a flat table.
void addTable(const engine::Table& table, Picture& picture);

}  // namespace baize::render

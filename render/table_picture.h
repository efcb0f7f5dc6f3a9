// A table as a player sees it from above, as draw items (render/draw_items.h): the wooden rail,
// the cushion rubber, the pocket holes, the cloth bounded by the real cushion outline (rails,
// jaws and facings from engine/table.h), diamonds and spots on pool tables, the baulk line, the D
// and the spots on snooker tables.
#pragma once

#include <vector>

#include "engine/table.h"
#include "render/draw_items.h"

namespace baize::render {

// Widths beyond the cushion nose, m: the cushion rubber, then the wooden rail up to the outer edge
// (wide enough to hold the diamonds, which sit about 0.09 m behind the nose).
constexpr double kCushionWidth_m = 0.05;
constexpr double kRailOuterEdge_m = 0.15;

// Colours of the table (not of the balls, which the ball set gives).
struct TableColours {
  Rgba cloth, cushion, rail, pocket, marking;
};
TableColours tableColours(engine::TableKind kind);

// The closed cushion outline around the cloth, counterclockwise: rails, jaw arcs (sampled),
// facings, and across each pocket from one facing's end to the other's.
std::vector<Eigen::Vector2d> clothOutline(const engine::Table& table);

// Appends the table's items to `picture` (bottom layers first) and sets its frame to the rail's
// outer edge.
void addTable(const engine::Table& table, Picture& picture);

}  // namespace baize::render

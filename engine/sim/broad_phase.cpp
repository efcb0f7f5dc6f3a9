#include "engine/sim/broad_phase.h"

#include <Eigen/Geometry>

namespace baize::engine {

RestingGrid::RestingGrid(const std::vector<int>& indices,
                         const std::vector<physics::BallState>& balls, double R) {
  if (indices.empty()) return;
  Eigen::AlignedBox2d extent;
  for (int i : indices) extent.extend(balls[i].position);
  origin_m_ = extent.min();
  const Eigen::Vector2d size = extent.sizes();
  const double per_cell = static_cast<double>(indices.size()) * kGridCellsPerBall;
  cell_m_ = std::max(
      {kGridCellRadii * R, std::sqrt(size.x() * size.y() / per_cell), size.maxCoeff() / per_cell});
  columns_ = cellOf(extent.max().x(), origin_m_.x(), kMaxCells) + 1;
  rows_ = cellOf(extent.max().y(), origin_m_.y(), kMaxCells) + 1;
  // Counting sort of the balls by cell: cell c holds members_[first_[c]] to
  // members_[first_[c+1]).
  std::vector<int> cell(indices.size());
  first_.assign(static_cast<std::size_t>(columns_) * rows_ + 1, 0);
  for (std::size_t k = 0; k < indices.size(); ++k) {
    const Eigen::Vector2d& q = balls[indices[k]].position;
    cell[k] =
        cellOf(q.y(), origin_m_.y(), rows_) * columns_ + cellOf(q.x(), origin_m_.x(), columns_);
    ++first_[cell[k] + 1];
  }
  for (std::size_t c = 1; c < first_.size(); ++c) first_[c] += first_[c - 1];
  members_.resize(indices.size());
  std::vector<int> filled(first_.begin(), first_.end() - 1);
  for (std::size_t k = 0; k < indices.size(); ++k) members_[filled[cell[k]]++] = indices[k];
}

}  // namespace baize::engine

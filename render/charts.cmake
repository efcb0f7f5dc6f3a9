# Line charts as PNG (render/chart_axis, render/line_chart), drawn with Cairo; text in DejaVu Sans
# (Debian libcairo2-dev, fonts-dejavu-core: tools/setup.sh). Sources are listed, not globbed, so
# the charts stay one library beside the other renderers in this directory.
find_package(PkgConfig REQUIRED)
pkg_check_modules(CAIRO REQUIRED IMPORTED_TARGET cairo)
add_library(baize_charts STATIC
  ${CMAKE_CURRENT_SOURCE_DIR}/chart_axis.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/line_chart.cpp)
baize_library_includes(baize_charts)
set_target_properties(baize_charts PROPERTIES EXPORT_NAME charts)
# Cairo is public: the tests decode the PNG files with it to check their pixels.
target_link_libraries(baize_charts PUBLIC baize_engine baize_physics PkgConfig::CAIRO)

// A Result as bytes and back, for pickle: Dask and multiprocessing send results between processes
// and machines. Every double goes as its 8 bytes, so the copy is the same to the bit; the outcome
// (pocketed, first ball hit, foul) is derived again from the events as simulate derives it.
#pragma once

#include <string>

#include "python/shot_run.h"

namespace baize::python {

// Makes the shot's derived parts first (python/shot_run.h): a result unpickled has no scene.
std::string shotRunBytes(ShotRun& shot);
// Throws pybind11::value_error when `bytes` is not what shotRunBytes wrote.
ShotRun shotRunFromBytes(const std::string& bytes);

}  // namespace baize::python

// A Result as bytes and back, for pickle: Dask and multiprocessing send results between processes
// and machines. Every double goes as its 8 bytes, so the copy is the same to the bit; the outcome
// (pocketed, first ball hit, foul) is derived again from the events as simulate derives it.
#pragma once

#include <string>

#include "python/result_bindings.h"

namespace baize::python {

std::string shotRunBytes(const ShotRun& shot);
// Throws pybind11::value_error when `bytes` is not what shotRunBytes wrote.
ShotRun shotRunFromBytes(const std::string& bytes);

}  // namespace baize::python

// Plain Python values as a JSON document: baize.Scene(...) builds the document a scene file would
// hold and hands it to the scene reader, so that its checks and messages are the file's.
#pragma once

#include <pybind11/pybind11.h>

#include <nlohmann/json.hpp>
#include <string>

namespace baize::python {

// dict (str keys), list, tuple, str, bool, int, float, None, numpy numbers and numpy arrays, nested.
// Throws pybind11::type_error naming `where` (the key path, "shot.speed_mps") and the type found
// for anything else, and pybind11::value_error for an int beyond 64 bits.
nlohmann::json jsonFromPython(pybind11::handle value, const std::string& where);

}  // namespace baize::python

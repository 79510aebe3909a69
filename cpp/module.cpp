// The private compiled module seaway._core: wiring only; each area registers itself.
#include <pybind11/pybind11.h>

#include "seaway/pages.hpp"

namespace py = pybind11;

void register_search(py::module_& m);
void register_weather(py::module_& m);
void register_models(py::module_& m);
void register_exact(py::module_& m);
void register_smooth(py::module_& m);
void register_turns(py::module_& m);
void register_constraints(py::module_& m);
void register_capabilities(py::module_& m);

PYBIND11_MODULE(_core, m) {
  m.doc() = "seaway's C++ engine (private: use the seaway package)";
  register_search(m);
  register_weather(m);
  register_models(m);
  register_exact(m);
  register_turns(m);
  register_constraints(m);
  register_smooth(m);  // after every model class (constraints: the zoned ones), for its signatures
  register_capabilities(m);  // last: every model class is registered
  m.attr("page_strategy") = seaway::pages::strategy;  // the search labels' memory (cpp/seaway/pages.hpp)
}

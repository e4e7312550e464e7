// A Python dict in the cell-file layout -> a TOML document for objective::readCellDocument, so a
// cell given from Python is read (and refused) exactly as the same cell file.
#include <cmath>

#include "common/errors.hpp"
#include "python/src/bindings.hpp"

namespace mesochain::python {

toml::value tomlFromPython(const py::handle& o, const std::string& source, const std::string& key) {
  const std::string where = key.empty() ? "the document" : "key " + key;
  // NumPy scalars and arrays: their Python equivalents.
  if (!py::isinstance<py::bool_>(o) && !py::isinstance<py::int_>(o) &&
      !py::isinstance<py::float_>(o) && !py::isinstance<py::str>(o) && py::hasattr(o, "tolist"))
    return tomlFromPython(o.attr("tolist")(), source, key);
  if (py::isinstance<py::bool_>(o)) return toml::value(o.cast<bool>());
  if (py::isinstance<py::int_>(o)) {
    try {
      return toml::value(o.cast<std::int64_t>());
    } catch (const py::cast_error&) {
      throw InputError(source, where, "an integer beyond 64 bits", "an integer that fits TOML");
    }
  }
  if (py::isinstance<py::float_>(o)) return toml::value(o.cast<double>());
  if (py::isinstance<py::str>(o)) return toml::value(o.cast<std::string>());
  if (py::isinstance<py::dict>(o)) {
    toml::table t;
    for (const auto& [k, v] : o.cast<py::dict>()) {
      if (!py::isinstance<py::str>(k))
        throw InputError(source, where, "a key that is not a string (" + py::repr(k).cast<std::string>() + ")",
                         "string keys, as in the cell file");
      const std::string name = k.cast<std::string>();
      t[name] = tomlFromPython(v, source, key.empty() ? name : key + "." + name);
    }
    return toml::value(std::move(t));
  }
  if (py::isinstance<py::list>(o) || py::isinstance<py::tuple>(o)) {
    toml::array a;
    std::size_t i = 0;
    for (const auto& v : o) a.push_back(tomlFromPython(v, source, key + "[" + std::to_string(i++) + "]"));
    return toml::value(std::move(a));
  }
  throw InputError(source, where,
                   "a Python " + py::str(py::type::handle_of(o).attr("__name__")).cast<std::string>(),
                   "a bool, int, float, str, list, tuple or dict (the types of the cell file)");
}

}  // namespace mesochain::python

// The project's errors as Python exceptions: InputError (a ValueError) carries `source` (the
// file, "<python>" or "<dict>") and `where` (line or key) as attributes; NumericalError is a
// RuntimeError. Both keep the C++ message, the same text as the command line prints.
#include <exception>

#include "common/errors.hpp"
#include "python/src/bindings.hpp"

namespace mesochain::python {

namespace {
PyObject* inputErrorType = nullptr;
PyObject* numericalErrorType = nullptr;

void raiseInputError(const InputError& e) {
  py::object type = py::reinterpret_borrow<py::object>(inputErrorType);
  py::object value = type(e.what());
  value.attr("source") = e.source();
  value.attr("where") = e.where();
  PyErr_SetObject(inputErrorType, value.ptr());
}
}  // namespace

void bindErrors(py::module_& m) {
  static py::exception<InputError> input(m, "InputError", PyExc_ValueError);
  static py::exception<NumericalError> numerical(m, "NumericalError", PyExc_RuntimeError);
  input.doc() =
      "Bad input: the message names the file (or <python>, <dict>, <atoms.info>), the line or key, "
      "what was found and what was expected. Attributes: source, where.";
  numerical.doc() = "A numerical failure that is not the user's fault (e.g. SCC not converged).";
  inputErrorType = input.ptr();
  numericalErrorType = numerical.ptr();
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      raiseInputError(e);
    } catch (const NumericalError& e) {
      PyErr_SetString(numericalErrorType, e.what());
    }
  });
  m.def(
      "input_error",
      [](const std::string& source, const std::string& where, const std::string& found,
         const std::string& expected) { throw InputError(source, where, found, expected); },
      py::arg("source"), py::arg("where"), py::arg("found"), py::arg("expected"),
      "Raise mesochain.InputError with the message composed as the library composes it.");
}

}  // namespace mesochain::python

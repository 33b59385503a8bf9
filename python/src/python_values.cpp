/*
 * pcl_flowseg Python bindings - Python objects to the conversion layer's values and back.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "python_values.h"

#include <pcl_flowseg/common/parameter_table.h>

#include <pybind11/stl.h>

#include <cstdint>

namespace pcl_flowseg_python {
namespace {

bool
isBool (const py::handle& value)
{
  static const py::object numpy_bool = py::module_::import ("numpy").attr ("bool_");
  return py::isinstance<py::bool_> (value) || py::isinstance (value, numpy_bool);
}

/** An int (or numpy integer) as int64; ValueError when it does not fit. */
std::int64_t
toInt64 (const std::string& name, const py::handle& value)
{
  const py::object index = py::reinterpret_steal<py::object> (PyNumber_Index (value.ptr ()));
  if (!index)
    throw py::error_already_set ();
  int overflow = 0;
  const long long v = PyLong_AsLongLongAndOverflow (index.ptr (), &overflow);
  if (overflow)
    throw py::value_error (name + ": the number is too large");
  return static_cast<std::int64_t> (v);
}

ArgumentValue
toValue (const std::string& name, const py::handle& value)
{
  if (value.is_none ())
    return std::monostate ();
  if (isBool (value))
    return static_cast<bool> (py::bool_ (py::reinterpret_borrow<py::object> (value)));
  if (PyIndex_Check (value.ptr ()))
    return toInt64 (name, value);
  if (py::isinstance<py::str> (value))
    return value.cast<std::string> ();
  if (py::isinstance<py::dict> (value)) // named weights: {"parts": 3.0, ...} as the text "parts=3,..."
  {
    std::string text;
    for (const auto& [key, item] : py::reinterpret_borrow<py::dict> (value))
    {
      if (!py::isinstance<py::str> (key) || isBool (item) || !(PyIndex_Check (item.ptr ()) || PyFloat_Check (item.ptr ())))
        throw py::value_error (name + ": needs a dict of names to numbers");
      text += (text.empty () ? "" : ",") + key.cast<std::string> () + "=" + pcl_flowseg::numberText (item.cast<double> ());
    }
    return text;
  }
  if (PyFloat_Check (value.ptr ()) || PyObject_HasAttrString (value.ptr (), "__float__"))
    return value.cast<double> ();
  if ((py::isinstance<py::sequence> (value) && !py::isinstance<py::bytes> (value)) || py::isinstance<py::array> (value))
  {
    std::vector<double> numbers;
    for (const py::handle item : py::iter (value))
    {
      if (isBool (item) || py::isinstance<py::str> (item) || !(PyIndex_Check (item.ptr ()) || PyObject_HasAttrString (item.ptr (), "__float__")))
        throw py::value_error (name + ": needs a sequence of numbers");
      numbers.push_back (item.cast<double> ());
    }
    return numbers;
  }
  throw py::value_error (name + ": unsupported type " + std::string (py::str (value.get_type ().attr ("__name__"))));
}

py::object
toPython (const ArgumentValue& value)
{
  if (std::holds_alternative<std::monostate> (value))
    return py::none ();
  if (const auto* b = std::get_if<bool> (&value))
    return py::bool_ (*b);
  if (const auto* i = std::get_if<std::int64_t> (&value))
    return py::int_ (*i);
  if (const auto* d = std::get_if<double> (&value))
    return py::float_ (*d);
  if (const auto* s = std::get_if<std::string> (&value))
    return py::str (*s);
  return py::tuple (py::cast (std::get<std::vector<double>> (value)));
}

} // namespace

Arguments
argumentsFromKwargs (const py::kwargs& kwargs)
{
  Arguments arguments;
  for (const auto& [key, value] : kwargs)
  {
    const std::string name = py::str (key);
    arguments.emplace_back (name, toValue (name, value));
  }
  return arguments;
}

void
applyKwargs (const py::kwargs& kwargs, unsigned groups, CallParameters& call, pcl_flowseg::MatchParameters& match)
{
  const Conversion c = applyArguments (argumentsFromKwargs (kwargs), groups, call, match);
  if (c.error == ArgumentError::UnknownName)
    throw py::type_error (c.message);
  if (!c)
    throw py::value_error (c.message);
  for (const std::string& warning : c.warnings)
    if (PyErr_WarnEx (PyExc_DeprecationWarning, warning.c_str (), 1) != 0)
      throw py::error_already_set ();
}

py::dict
argumentsToDict (const Arguments& arguments)
{
  py::dict d;
  for (const auto& [name, value] : arguments)
    d[py::str (name)] = toPython (value);
  return d;
}

std::vector<Eigen::Vector3d>
pointsFromPython (const py::handle& object, const std::string& what, bool require_finite)
{
  if (!py::isinstance<py::array> (object))
    throw py::value_error (what + ": needs a numpy array of shape (n, 2) or (n, 3), got " +
                           std::string (py::str (object.get_type ().attr ("__name__"))));
  const py::array array = py::reinterpret_borrow<py::array> (object);
  ArrayView view;
  view.data = array.data ();
  view.kind = array.dtype ().kind ();
  view.item_size = static_cast<std::size_t> (array.itemsize ());
  for (py::ssize_t axis = 0; axis < array.ndim (); ++axis)
  {
    view.shape.push_back (array.shape (axis));
    view.strides.push_back (array.strides (axis));
  }
  std::vector<Eigen::Vector3d> points;
  if (const Conversion c = pointsFromArray (view, what, require_finite, 0, points); !c)
    throw py::value_error (c.message);
  return points;
}

void
raiseIfFailed (const pcl_flowseg::Status& status)
{
  if (!status)
    throw py::value_error (status.message);
}

void
raiseOsErrorIfFailed (const pcl_flowseg::Status& status)
{
  if (!status)
  {
    PyErr_SetString (PyExc_OSError, status.message.c_str ());
    throw py::error_already_set ();
  }
}

void
warnDeprecated (const char* message)
{
  if (PyErr_WarnEx (PyExc_DeprecationWarning, message, 1) != 0)
    throw py::error_already_set ();
}

py::array_t<double>
rowsToArray (const std::vector<Eigen::Vector3d>& rows)
{
  py::array_t<double> out ({static_cast<py::ssize_t> (rows.size ()), py::ssize_t (3)});
  auto view = out.mutable_unchecked<2> ();
  for (std::size_t i = 0; i < rows.size (); ++i)
    for (int c = 0; c < 3; ++c)
      view (static_cast<py::ssize_t> (i), c) = rows[i][c];
  return out;
}

} // namespace pcl_flowseg_python

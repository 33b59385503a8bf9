/*
 * pcl_flowseg Python bindings - Python objects to the conversion layer's values and back, and the
 * library's failures as Python exceptions.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include "argument_conversion.h"

#include <pcl_flowseg/common/status.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace pcl_flowseg_python {

namespace py = pybind11;

/** \brief The keyword arguments of a call as the conversion layer's values; ValueError for a value
  * of no supported type. */
Arguments
argumentsFromKwargs (const py::kwargs& kwargs);

/** \brief Applies \a kwargs (see applyArguments) and raises TypeError / ValueError on failure. */
void
applyKwargs (const py::kwargs& kwargs, unsigned groups, CallParameters& call, pcl_flowseg::MatchParameters& match);

/** \brief \a arguments as a Python dict. */
py::dict
argumentsToDict (const Arguments& arguments);

/** \brief An (n, 2) or (n, 3) float array as points; ValueError on anything else. */
std::vector<Eigen::Vector3d>
pointsFromPython (const py::handle& array, const std::string& what, bool require_finite);

/** \brief Raises ValueError with the library's message when \a status is a failure. */
void
raiseIfFailed (const pcl_flowseg::Status& status);

/** \brief Raises OSError (file problems: a missing, unreadable or damaged file) on failure. */
void
raiseOsErrorIfFailed (const pcl_flowseg::Status& status);

/** \brief Warns with DeprecationWarning \a message (raises when warnings are errors). */
void
warnDeprecated (const char* message);

/** \brief An (n, 3) float64 array of \a rows. */
py::array_t<double>
rowsToArray (const std::vector<Eigen::Vector3d>& rows);

} // namespace pcl_flowseg_python

/*
 * pcl_flowseg Python bindings - Python's arguments as the library's types, without Python:
 * keyword values to parameters and strided arrays to points, every value checked. Kept free of
 * pybind11 so that the fuzz target fuzz_python_arguments exercises exactly this code.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/flow_parameters.h>
#include <pcl_flowseg/common/status.h>
#include <pcl_flowseg/io/shape_input.h>
#include <pcl_flowseg/signature/signature_parameters.h>
#include <pcl_flowseg/signature/signature_matcher.h>

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace pcl_flowseg_python {

/** \brief A keyword argument's value as Python gave it: None, bool, int, float, str, or a sequence
  * of numbers. */
using ArgumentValue = std::variant<std::monostate, bool, std::int64_t, double, std::string, std::vector<double>>;
using Arguments = std::vector<std::pair<std::string, ArgumentValue>>;

/** \brief Everything segment() and the signature functions take, parsed from keywords: the
  * signature parameters (significance, input) and the segmentation's. */
struct CallParameters : pcl_flowseg::SignatureParameters
{
  pcl_flowseg::FlowParameters flow;
};

/** \brief Which keyword groups a call accepts. */
enum ArgumentGroups : unsigned
{
  kFlowArguments = 1u,         ///< flowParameterTable (rho, threads, viewpoint, ...)
  kSignificanceArgument = 2u,  ///< signatureParameterTable's significance
  kShapeInputArguments = 4u,   ///< signatureParameterTable's input rows (mesh_points, seed, ...)
  kMatchArguments = 8u         ///< threshold, allow_mirror, alignment_points
};

/** \brief Error kinds, so that the bindings raise what Python expects. */
enum class ArgumentError
{
  None,
  UnknownName, ///< TypeError: the call takes no such keyword
  BadValue     ///< ValueError: wrong type or out of range (the library's message)
};

/** \brief The outcome of a conversion: ok, or the error kind and a message. */
struct Conversion
{
  ArgumentError error = ArgumentError::None;
  std::string message;
  std::vector<std::string> warnings; ///< old spellings used: Python issues a DeprecationWarning each
  explicit operator bool () const { return error == ArgumentError::None; }
};

/** \brief Applies \a arguments of the groups \a groups to \a call and \a match (either may be
  * unused), each name once, then checks the results with the library's checks. The keywords and
  * their values are those of flowParameterTable and signatureParameterTable (old spellings are
  * accepted and reported in Conversion::warnings). */
Conversion
applyArguments (const Arguments& arguments, unsigned groups, CallParameters& call, pcl_flowseg::MatchParameters& match);

/** \brief The keyword form of \a params, a keyword per row of flowParameterTable (choices as
  * their names, viewpoint None or three numbers): applyArguments of it gives \a params back. */
Arguments
flowArguments (const pcl_flowseg::FlowParameters& params);

/** \brief The keyword form of \a params, a keyword per row of signatureParameterTable. */
Arguments
signatureArguments (const pcl_flowseg::SignatureParameters& params);

/** \brief The keyword form of \a match. */
Arguments
matchArguments (const pcl_flowseg::MatchParameters& match);

/** \brief A two-dimensional numeric array as the buffer protocol describes it. */
struct ArrayView
{
  const void* data = nullptr;
  char kind = 'f';              ///< numpy dtype kind: 'f' float, 'i'/'u' integer, 'b' bool, ...
  std::size_t item_size = 8;    ///< bytes per element
  std::vector<std::int64_t> shape;   ///< the array's shape
  std::vector<std::int64_t> strides; ///< in bytes, one per axis
};

/** \brief Copies an (n, 2) or (n, 3) float32/float64 array into points (z = 0 for n x 2); \a what
  * names the argument in messages. Refuses other shapes and dtypes, and strides that leave the
  * buffer's \a buffer_bytes (when not 0). Non-finite values are kept (the segmentation counts them)
  * unless \a require_finite. */
Conversion
pointsFromArray (const ArrayView& array, const std::string& what, bool require_finite, std::size_t buffer_bytes,
                 std::vector<Eigen::Vector3d>& points);

} // namespace pcl_flowseg_python

/*
 * pcl_flowseg Python bindings - the parts of the module, one per layer of the library.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pybind11/pybind11.h>

namespace pcl_flowseg_python {

void bindSegmentation (pybind11::module_& m); ///< segment(), Segmentation, Feature, defaults
void bindSignature (pybind11::module_& m);    ///< Signature, signature functions, match()
void bindDatabase (pybind11::module_& m);     ///< Database, QueryHit
void bindIo (pybind11::module_& m);           ///< read_points, shape files

} // namespace pcl_flowseg_python

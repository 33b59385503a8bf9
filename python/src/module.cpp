/*
 * pcl_flowseg Python bindings - the extension module _pcl_flowseg (imported by the package
 * pcl_flowseg, which documents the whole API).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "bindings.h"
#include "python_values.h"

#include <pcl_flowseg/common/flow_parameter_table.h>
#include <pcl_flowseg/signature/signature_database.h>

PYBIND11_MODULE (_pcl_flowseg, m)
{
  using namespace pcl_flowseg_python;
  m.doc () = "pcl_flowseg: shape segmentation and matching by flow discretization (Dey, Giesen, Goswami).";
  bindSignature (m); // before segmentation: Segmentation.signature() returns a Signature
  bindSegmentation (m);
  bindDatabase (m);
  bindIo (m);
  m.def ("defaults", [] () {
    CallParameters call;
    py::dict d = argumentsToDict (flowArguments (call.flow));
    for (const auto& [name, value] : argumentsToDict (signatureArguments (call)))
      d[name] = value;
    for (const auto& [name, value] : argumentsToDict (matchArguments (pcl_flowseg::MatchParameters ())))
      d[name] = value;
    d["k"] = pcl_flowseg::kDefaultQueryResults;
    d["candidates"] = pcl_flowseg::kDefaultCandidates;
    return d;
  }, "Every keyword of the module's functions with its default (the C++ defaults, from the library).");
  m.def ("paper_rule", [] (double rho) {
    pcl_flowseg::FlowParameters params;
    params.merge = pcl_flowseg::MergeParameters::paperRule (rho);
    const Arguments all = flowArguments (params);
    Arguments merge;
    for (const auto& spec : pcl_flowseg::flowParameterTable ().specs)
      if (spec.info.group == "merge" && spec.info.name != "compact_rho")
        for (const auto& argument : all)
          if (argument.first == spec.info.name)
            merge.push_back (argument);
    return argumentsToDict (merge);
  }, py::arg ("rho") = pcl_flowseg::MergeParameters ().rho,
     "The merge keywords of the paper's rule alone at rho: segment(points, **paper_rule(1.3)).");
}

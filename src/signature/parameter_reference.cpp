/*
 * pcl_flowseg - the reference of every parameter, made from the parameter tables.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/signature/parameter_reference.h>

#include <pcl_flowseg/common/flow_parameter_table.h>
#include <pcl_flowseg/signature/match_parameter_table.h>
#include <pcl_flowseg/signature/signature_parameters.h>

namespace pcl_flowseg {

std::string
parameterReferenceMarkdown ()
{
  std::string out;
  out += "### Segmentation: `FlowParameters`\n\n" + parameterTableMarkdown (flowParameterTable ());
  out += "\n### Signatures: `SignatureParameters`\n\n" + parameterTableMarkdown (signatureParameterTable ());
  out += "\n### Matching: `MatchParameters`\n\n" + parameterTableMarkdown (matchParameterTable ());
  return out;
}

} // namespace pcl_flowseg

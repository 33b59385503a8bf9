/*
 * pcl_flowseg - how shape files become signatures, and the table that describes it.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/common/parameter_fields.h>
#include <pcl_flowseg/signature/signature_parameters.h>

#include <cstdint>
#include <limits>

namespace pcl_flowseg {

Status
checkSignatureParameters (const SignatureParameters& params)
{
  if (const Status s = checkSignificance (params.significance); !s)
    return s;
  return checkShapeInputOptions (params.input);
}

const ParameterTable<SignatureParameters>&
signatureParameterTable ()
{
  using SP = SignatureParameters;
  static const ParameterTable<SP> table = [] {
    ParameterTable<SP> t;
    t.title = "signatures (SignatureParameters)";
    t.specs.push_back (numberField<SP> ({"significance", "", "signature", ParameterType::Number, "share of the interior volume",
                                         "[0, 1)", "features above this share of the volume are significant"},
                                        [] (SP& p) -> double& { return p.significance; }));
    t.specs.push_back (countField<SP, std::size_t> ({"mesh_points", "", "input", ParameterType::Count, "points", "4 to 10^8",
                                                     "points sampled area-uniformly on a mesh's faces"},
                                                    [] (SP& p) -> std::size_t& { return p.input.mesh_points; }, 100000000ULL));
    t.specs.push_back (countField<SP, std::uint32_t> ({"seed", "", "input", ParameterType::Count, "", "0 to 2^32 - 1",
                                                       "seed of the sampling on meshes"},
                                                      [] (SP& p) -> std::uint32_t& { return p.input.seed; },
                                                      std::numeric_limits<std::uint32_t>::max ()));
    t.specs.push_back (switchField<SP> ({"use_sensor_origin", "", "input", ParameterType::Switch, "", "true, false",
                                         "the viewpoint of a single-view scan is each PCD file's own sensor origin (VIEWPOINT)"},
                                        [] (SP& p) -> bool& { return p.input.use_sensor_origin; }));
    t.check = [] (const SP& p) { return checkSignatureParameters (p); };
    return t;
  }();
  return table;
}

} // namespace pcl_flowseg

// Fuzzes the whole segmentation with arbitrary small point sets: byte 0 picks the dimension mode
// and the feature side, byte 1 rho; then 3 x int16 per point (with rare NaN/Inf and huge values).
#include <pcl_flowseg/segmentation/flow_pipeline.h>
#include <pcl_flowseg/signature/signature.h>

#include <cmath>
#include <cstdint>
#include <array>
#include <cstring>
#include <limits>

extern "C" int
LLVMFuzzerTestOneInput (const std::uint8_t* data, std::size_t size)
{
  if (size < 2)
    return 0;
  pcl_flowseg::FlowParameters params;
  params.preparation.dimension = static_cast<pcl_flowseg::DimensionMode> (std::array<int, 3>{{0, 2, 3}}[data[0] % 3]);
  params.features = static_cast<pcl_flowseg::FeatureSide> ((data[0] / 3) % 3);
  params.interior.separate = (data[0] / 9) % 4 != 0;
  params.interior.denoising = static_cast<pcl_flowseg::Denoising> ((data[0] / 36) % 3);
  params.merge.rho = 0.5 + data[1] / 64.0;
  std::vector<Eigen::Vector3d> points;
  for (std::size_t at = 2; at + 6 <= size && points.size () < 400; at += 6)
  {
    std::int16_t c[3];
    std::memcpy (c, data + at, 6);
    Eigen::Vector3d p (c[0], c[1], c[2]);
    if (c[0] == 32767)
      p.x () = std::numeric_limits<double>::quiet_NaN ();
    if (c[1] == -32768)
      p.y () = std::ldexp (1.0, 40);
    points.push_back (p / 256.0);
  }
  pcl_flowseg::FlowResult r;
  if (pcl_flowseg::runFlowSegmentation (points, params, r).ok)
  {
    if (r.point_labels.size () != points.size ())
      __builtin_trap ();
    for (const auto& c : r.cells)
      if (c.segment < 0 || static_cast<std::size_t> (c.segment) >= r.segments.size ())
        __builtin_trap ();
    pcl_flowseg::Signature s;
    pcl_flowseg::signatureFromSegmentation (r, 0.02, s);
    pcl_flowseg::MergeParameters merge;
    merge.rho = 2.0;
    pcl_flowseg::remergeFlowSegmentation (merge, r);
  }
  return 0;
}

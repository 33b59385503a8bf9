// Fuzzes the Python bindings' argument conversion (python/src/argument_conversion.cpp): arbitrary
// keyword names and values of every Python type, and arbitrary array descriptions (dtype, shape,
// strides) over the fuzz input as the buffer. A conversion must either refuse or give parameters
// the library accepts and that convert back to the same keywords; no array read may leave its buffer.
#include "argument_conversion.h"

#include <fuzzer/FuzzedDataProvider.h>

#include <cstdlib>

namespace {

using namespace pcl_flowseg_python;

const char* const kNames[] = {"dimension", "planar_tolerance", "rho", "sampling_tolerance", "stump_ratio", "compact_rho",
                              "compact_size", "min_part_share", "single_view_min_part_share", "separate", "denoising",
                              "viewpoint", "features", "threads", "memory_limit",
                              "significance", "mesh_points", "seed", "threshold", "allow_mirror", "alignment_points",
                              "separate_interior", "outliers", "smoothing", "smoothing_passes", "manifold_repair",
                              "hidden_side", "use_sensor_origin", "method", "weights_3d", "weights_2d"};

ArgumentValue
fuzzValue (FuzzedDataProvider& in)
{
  switch (in.ConsumeIntegralInRange<int> (0, 5))
  {
  case 0: return std::monostate ();
  case 1: return in.ConsumeBool ();
  case 2: return in.ConsumeIntegral<std::int64_t> ();
  case 3: return in.ConsumeFloatingPoint<double> ();
  case 4: return in.ConsumeRandomLengthString (16);
  default:
  {
    std::vector<double> numbers (in.ConsumeIntegralInRange<std::size_t> (0, 5));
    for (double& x : numbers)
      x = in.ConsumeFloatingPoint<double> ();
    return numbers;
  }
  }
}

void
fuzzKeywords (FuzzedDataProvider& in)
{
  Arguments arguments (in.ConsumeIntegralInRange<std::size_t> (0, 6));
  for (auto& [name, value] : arguments)
  {
    name = in.ConsumeBool () ? std::string (kNames[in.ConsumeIntegralInRange<std::size_t> (0, std::size (kNames) - 1)])
                             : in.ConsumeRandomLengthString (12);
    value = fuzzValue (in);
  }
  const unsigned groups = in.ConsumeIntegralInRange<unsigned> (0, 15);
  CallParameters call;
  pcl_flowseg::MatchParameters match;
  if (!applyArguments (arguments, groups, call, match))
    return;
  if (groups & kFlowArguments)
  {
    CallParameters again;
    pcl_flowseg::MatchParameters unused;
    if (!pcl_flowseg::checkParameters (call.flow) || !applyArguments (flowArguments (call.flow), kFlowArguments, again, unused) ||
        flowArguments (again.flow) != flowArguments (call.flow))
      std::abort (); // accepted parameters must be valid and survive the round trip
  }
  if ((groups & kMatchArguments) && !pcl_flowseg::checkMatchParameters (match))
    std::abort ();
}

void
fuzzArray (FuzzedDataProvider& in)
{
  static const char kinds[] = {'f', 'i', 'u', 'b', 'c', 'O', 'U'};
  static const std::size_t sizes[] = {1, 2, 4, 8, 16};
  ArrayView view;
  view.kind = kinds[in.ConsumeIntegralInRange<std::size_t> (0, std::size (kinds) - 1)];
  view.item_size = sizes[in.ConsumeIntegralInRange<std::size_t> (0, std::size (sizes) - 1)];
  const std::size_t axes = in.ConsumeIntegralInRange<std::size_t> (0, 3);
  for (std::size_t a = 0; a < axes; ++a)
  {
    view.shape.push_back (in.ConsumeIntegralInRange<std::int64_t> (-2, 40));
    view.strides.push_back (in.ConsumeIntegralInRange<std::int64_t> (-64, 64));
  }
  const std::vector<std::uint8_t> buffer = in.ConsumeRemainingBytes<std::uint8_t> ();
  view.data = buffer.empty () ? nullptr : buffer.data ();
  std::vector<Eigen::Vector3d> points;
  const bool finite = (buffer.size () & 1) != 0;
  if (pointsFromArray (view, "points", finite, buffer.size (), points) && points.size () != static_cast<std::size_t> (view.shape[0]))
    std::abort ();
}

} // namespace

extern "C" int
LLVMFuzzerTestOneInput (const std::uint8_t* data, std::size_t size)
{
  FuzzedDataProvider in (data, size);
  fuzzKeywords (in);
  fuzzArray (in);
  return 0;
}

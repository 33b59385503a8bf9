// Segments a generated dumbbell through the installed package; exits 0 when the two bulbs
// come out as two finite segments.
#include <pcl_flowseg/flow_segmentation.h>
#include <pcl_flowseg/shape_generator.h>

#include <iostream>

int
main ()
{
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
  for (const auto& p : pcl_flowseg::sampleBoundary (pcl_flowseg::sampleShape ("dumbbell2d"), 800, 1))
    cloud->push_back (pcl::PointXYZ (static_cast<float> (p.x ()), static_cast<float> (p.y ()), 0.0f));
  pcl::FlowSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud (cloud);
  std::vector<pcl::PointIndices> segments;
  if (!seg.segment (segments))
    return 1;
  std::cout << "consumer: " << segments.size () << " segments\n";
  return segments.size () >= 3 ? 0 : 1;
}

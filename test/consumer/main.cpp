// Segments a generated dumbbell through the installed package (both libraries: the shape generator
// is in pcl_flowseg_eval); exits 0 when the two bulbs and the neck come out as segments.
#include <pcl_flowseg/segmentation/flow_segmentation.h>
#include <pcl_flowseg/evaluation/shape_generator.h>

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

#include <pcl_flowseg/flow_core.h>
#include <gtest/gtest.h>
TEST (Smoke, Builds) { SUCCEED (); }

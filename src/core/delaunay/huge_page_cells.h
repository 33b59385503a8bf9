/*
 * pcl_flowseg - internal: the cells and vertices of CGAL's parallel triangulation on huge pages.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include "core/support/huge_page_arena.h"

#include <tbb/scalable_allocator.h>

namespace pcl_flowseg {
namespace core {

/** \brief A CGAL cell or vertex base under a name of this module, so that the allocator of its
  * container can be chosen. CGAL's parallel triangulation data structure always stores them with
  * tbb::scalable_allocator; the specialisation below sends that allocator's requests to the
  * HugePageArena. Everything else is the \a Base's. */
template <class Base>
struct OnHugePages : Base
{
  using Base::Base;

  template <class DataStructure>
  struct Rebind_TDS
  {
    using Other = OnHugePages<typename Base::template Rebind_TDS<DataStructure>::Other>;
  };
};

} // namespace core
} // namespace pcl_flowseg

namespace tbb {
namespace detail {
namespace d1 {
/** TBB's allocator of this module's triangulation elements: the blocks of CGAL's
  * Concurrent_compact_container, from the HugePageArena. */
template <class Base>
class scalable_allocator<pcl_flowseg::core::OnHugePages<Base>>
    : public pcl_flowseg::core::HugePageArenaAllocator<pcl_flowseg::core::OnHugePages<Base>>
{
public:
  scalable_allocator () = default;
  template <class U>
  scalable_allocator (const scalable_allocator<U>&) {}
};
} // namespace d1
} // namespace detail
} // namespace tbb

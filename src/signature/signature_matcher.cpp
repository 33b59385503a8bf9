/*
 * pcl_flowseg - comparing two signatures: by their descriptions, or by the paper's alignment search
 * and score (section 5).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <pcl_flowseg/signature/signature_matcher.h>

#include "description_distances.h"
#include "view_distance.h"

#include <flann/flann.hpp>
#include <pcl/console/print.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pcl {

namespace {

using pcl_flowseg::Signature;

/** Nearest neighbours among the points of one signature: FLANN k-d tree for large signatures;
  * for the usual handful of points a direct scan, which is several times faster than a tree query
  * and gives the same answers (same float arithmetic, ties to the lower index). */
class PointIndex
{
public:
  static constexpr std::size_t kScanBelow = 48;

  explicit PointIndex (const Signature& s) : data_ (3 * std::max<std::size_t> (1, s.points.size ()), 0.0f), count_ (s.points.size ())
  {
    for (std::size_t i = 0; i < s.points.size (); ++i)
      for (int k = 0; k < 3; ++k)
        data_[3 * i + static_cast<std::size_t> (k)] = static_cast<float> (s.points[i].position[k]);
    if (count_ >= kScanBelow)
    {
      index_.reset (new flann::Index<flann::L2_Simple<float>> (flann::Matrix<float> (data_.data (), s.points.size (), 3),
                                                               flann::KDTreeSingleIndexParams (4)));
      index_->buildIndex ();
    }
  }

  /** Nearest point (index, squared distance) of each of \a count queries (x y z floats), in one call. */
  void
  nearest (std::vector<float>& queries, std::size_t count, std::vector<int>& ids, std::vector<float>& dist) const
  {
    ids.assign (count, -1);
    dist.assign (count, 0.0f);
    if (count_ < kScanBelow)
    {
      for (std::size_t q = 0; q < count; ++q)
      {
        const float* x = &queries[3 * q];
        float best = std::numeric_limits<float>::infinity ();
        for (std::size_t i = 0; i < count_; ++i)
        {
          const float* p = &data_[3 * i];
          const float d0 = x[0] - p[0], d1 = x[1] - p[1], d2 = x[2] - p[2];
          const float d = d0 * d0 + d1 * d1 + d2 * d2;
          if (d < best)
          {
            best = d;
            ids[q] = static_cast<int> (i);
          }
        }
        dist[q] = best;
      }
      return;
    }
    flann::Matrix<float> qm (queries.data (), count, 3);
    flann::Matrix<int> im (ids.data (), count, 1);
    flann::Matrix<float> dm (dist.data (), count, 1);
    index_->knnSearch (qm, im, dm, 1, search_);
  }

  flann::SearchParams search_ = flann::SearchParams (flann::FLANN_CHECKS_UNLIMITED);

private:
  std::vector<float> data_;
  std::size_t count_ = 0;
  std::unique_ptr<flann::Index<flann::L2_Simple<float>>> index_;
};

/** Rotation taking unit vector \a from to unit vector \a to. */
Eigen::Matrix3d
rotationBetween (const Eigen::Vector3d& from, const Eigen::Vector3d& to)
{
  return Eigen::Quaterniond::FromTwoVectors (from, to).toRotationMatrix ();
}

/** Scores alignments of signature b onto signature a and keeps the best in \a best. */
class AlignmentScorer
{
public:
  AlignmentScorer (const Signature& a, const Signature& b, double threshold, SignatureMatcher::Result& best)
    : a_ (a), b_ (b), index_ (a), threshold2_ (threshold * threshold), best_ (best), partner_of_a_ (a.points.size ()),
      queries_ (3 * b.points.size ())
  {
  }

  /** The paper's score of x_a = linear * x_b + translation: every point of b whose nearest point
    * of a lies within the threshold adds 1 - |w_p - w_q| / (w_p + w_q); every point of either
    * without a partner subtracts its weight. */
  void
  score (const Eigen::Matrix3d& linear, const Eigen::Vector3d& translation, bool mirrored)
  {
    std::fill (partner_of_a_.begin (), partner_of_a_.end (), 0);
    pairs_.clear ();
    for (std::size_t j = 0; j < b_.points.size (); ++j)
    {
      const Eigen::Vector3d q = linear * b_.points[j].position + translation;
      for (int k = 0; k < 3; ++k)
        queries_[3 * j + static_cast<std::size_t> (k)] = static_cast<float> (q[k]);
    }
    index_.nearest (queries_, b_.points.size (), ids_, dist_);
    double s = 0.0;
    for (std::size_t j = 0; j < b_.points.size (); ++j)
    {
      const double wq = b_.points[j].weight;
      if (ids_[j] >= 0 && dist_[j] <= threshold2_)
      {
        const double wp = a_.points[static_cast<std::size_t> (ids_[j])].weight;
        s += 1.0 - std::abs (wp - wq) / (wp + wq);
        partner_of_a_[static_cast<std::size_t> (ids_[j])] = 1;
        pairs_.emplace_back (ids_[j], static_cast<int> (j));
      }
      else
        s -= wq;
    }
    for (std::size_t i = 0; i < a_.points.size (); ++i)
      if (!partner_of_a_[i])
        s -= a_.points[i].weight;
    ++best_.alignments;
    if (s > best_.paper_score)
    {
      best_.paper_score = s;
      best_.linear = linear;
      best_.translation = translation;
      best_.mirrored = mirrored;
      best_.pairs = pairs_;
    }
  }

private:
  const Signature& a_;
  const Signature& b_;
  const PointIndex index_;
  const double threshold2_;
  SignatureMatcher::Result& best_;
  std::vector<int> partner_of_a_;
  std::vector<std::pair<int, int>> pairs_;
  std::vector<float> queries_;
  std::vector<int> ids_;
  std::vector<float> dist_;
};

/** The alignments that turn b's segment (heaviest point, point j) onto a's (heaviest, point i):
  * in 3D the rotation about that axis is fixed by every pair of third points (k of a, l of b);
  * without such a pair the axis alignment alone is scored. \a m mirrors b or not. */
void
scoreAlongAxis (const Signature& a, const Signature& b, std::size_t i, std::size_t j, std::size_t ma, std::size_t mb,
                const Eigen::Matrix3d& m, bool mirrored, AlignmentScorer& scorer)
{
  const Eigen::Vector3d a0 = a.points[0].position;
  const Eigen::Vector3d b0 = m * b.points[0].position;
  const Eigen::Vector3d axis = (a.points[i].position - a0).normalized ();
  const Eigen::Matrix3d r1 = rotationBetween ((m * b.points[j].position - b0).normalized (), axis);
  bool fixed = false;
  for (std::size_t k = 1; k < ma; ++k)
  {
    if (k == i)
      continue;
    Eigen::Vector3d pa = a.points[k].position - a0;
    pa -= pa.dot (axis) * axis;
    if (pa.norm () < 1e-9)
      continue;
    for (std::size_t l = 1; l < mb; ++l)
    {
      if (l == j)
        continue;
      Eigen::Vector3d pb = r1 * (m * b.points[l].position - b0);
      pb -= pb.dot (axis) * axis;
      if (pb.norm () < 1e-9)
        continue;
      const double angle = std::atan2 (axis.dot (pb.cross (pa)), pb.dot (pa));
      const Eigen::Matrix3d r = Eigen::AngleAxisd (angle, axis).toRotationMatrix () * r1;
      scorer.score (r * m, a0 - r * b0, mirrored);
      fixed = true;
    }
  }
  if (!fixed)
    scorer.score (r1 * m, a0 - r1 * b0, mirrored);
}

/** A single view against a complete shape's views (either order), or two single views. Infinite
  * when either side has no view (a 2D shape, or a signature read from an older file). */
double
singleViewDistance (const pcl_flowseg::ViewSet& a, const pcl_flowseg::ViewSet& b)
{
  if (a.views.empty () || b.views.empty ())
    return std::numeric_limits<double>::infinity ();
  if (a.single_view && b.single_view)
    return std::min (pcl_flowseg::internal::viewDistance (a.views[0], b.views[0]),
                     pcl_flowseg::internal::viewDistance (b.views[0], a.views[0]));
  const pcl_flowseg::ViewSet& scan = a.single_view ? a : b;
  const pcl_flowseg::ViewSet& shape = a.single_view ? b : a;
  return pcl_flowseg::internal::singleViewDistance (scan.views[0], shape);
}

} // namespace

SignatureMatcher::Result
SignatureMatcher::alignOnto (const Signature& a, const Signature& b) const
{
  const pcl_flowseg::PaperMatchParameters& paper = params_.paper;
  Result best;
  best.paper_score = -std::numeric_limits<double>::infinity ();
  AlignmentScorer scorer (a, b, paper.threshold, best);
  const std::size_t ma = std::min<std::size_t> (a.points.size (), static_cast<std::size_t> (paper.alignment_points));
  const std::size_t mb = std::min<std::size_t> (b.points.size (), static_cast<std::size_t> (paper.alignment_points));
  const Eigen::Vector3d a0 = a.points[0].position;
  for (int mirror = 0; mirror < (paper.allow_mirror ? 2 : 1); ++mirror)
  {
    const Eigen::Matrix3d m = mirror ? Eigen::Vector3d (-1, 1, 1).asDiagonal ().toDenseMatrix () : Eigen::Matrix3d::Identity ();
    const Eigen::Vector3d b0 = m * b.points[0].position;
    // Heaviest points together, no rotation: the only alignment when either has a single point.
    scorer.score (m, a0 - b0, mirror == 1);
    for (std::size_t i = 1; i < ma; ++i)
      for (std::size_t j = 1; j < mb; ++j)
        if ((a.points[i].position - a0).norm () != 0.0 && (m * b.points[j].position - b0).norm () != 0.0)
          scoreAlongAxis (a, b, i, j, ma, mb, m, mirror == 1, scorer);
  }
  return best;
}

SignatureMatcher::Result
SignatureMatcher::match (const Signature& a, const Signature& b) const
{
  Result r;
  r.status = pcl_flowseg::checkMatchParameters (params_);
  if (r.status && params_.method != pcl_flowseg::MatchMethod::Paper && (a.description.empty () || b.description.empty ()))
    r.status = pcl_flowseg::Status::error (std::string ("the method ") + pcl_flowseg::matchMethodName (params_.method) +
                                           " needs signatures with shape descriptions (rebuild older ones)");
  if (r.status && params_.method != pcl_flowseg::MatchMethod::Paper && a.dimension != b.dimension)
    r.status = pcl_flowseg::Status::error ("cannot compare a 2D with a 3D signature");
  if (!r.status)
  {
    PCL_ERROR ("[pcl::SignatureMatcher::match] %s\n", r.status.message.c_str ());
    r.similarity = -std::numeric_limits<double>::infinity ();
    return r;
  }
  if (params_.method == pcl_flowseg::MatchMethod::Paper)
    return matchPaper (a, b);
  if (a.views.single_view || b.views.single_view) // a scan: aligned with the other's views
  {
    r.distance = singleViewDistance (a.views, b.views);
    r.similarity = std::exp (-r.distance);
    return r;
  }
  r.distance = pcl_flowseg::descriptionDistance (pcl_flowseg::descriptionWeights (params_, a.dimension), a.description,
                                                 b.description); // symmetric
  r.similarity = std::exp (-r.distance);
  return r;
}

SignatureMatcher::Result
SignatureMatcher::matchPaper (const Signature& a, const Signature& b) const
{
  Result r;
  if (a.points.empty () || b.points.empty ())
  {
    r.paper_score = 0.0;
    for (const auto& p : a.points)
      r.paper_score -= p.weight;
    for (const auto& p : b.points)
      r.paper_score -= p.weight;
    r.similarity = a.points.empty () && b.points.empty () ? 0.0 : r.paper_score;
    return r;
  }
  Result ab = alignOnto (a, b);
  Result ba = alignOnto (b, a);
  const std::size_t alignments = ab.alignments + ba.alignments;
  if (ba.paper_score > ab.paper_score)
  {
    // Invert: x_b = L x_a + t  =>  x_a = L^T (x_b - t) (L is orthogonal).
    r = ba;
    r.linear = ba.linear.transpose ();
    r.translation = -(ba.linear.transpose () * ba.translation);
    for (auto& p : r.pairs)
      std::swap (p.first, p.second);
  }
  else
    r = ab;
  r.alignments = alignments;
  r.similarity = r.paper_score / static_cast<double> (std::max (a.points.size (), b.points.size ()));
  return r;
}

} // namespace pcl

/*
 * pcl_flowseg - comparing two signatures: their shape descriptions (the default), or the paper's
 * alignment search and score (section 5).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>
#include <pcl_flowseg/signature/match_method.h>
#include <pcl_flowseg/signature/match_parameters.h>
#include <pcl_flowseg/signature/signature.h>

#include <pcl/memory.h>
#include <pcl/pcl_macros.h>

#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace pcl {

/** \brief Compares two shape signatures; invariant to translation, rotation, mirroring and scale.
  *
  * By default (pcl_flowseg::MatchMethod::Combined) and with the other description methods it
  * compares the signatures' shape descriptions: the weighted sum d of the method's description
  * distances (pcl_flowseg::descriptionWeights; 0 for identical descriptions) gives the similarity
  * exp(-d), in (0, 1]; nothing is aligned.
  *
  * MatchMethod::Paper is the paper's alignment search (MatchParameters::paper): the heaviest points
  * of the two signatures are made to coincide, then the segment from the heaviest point to another
  * point of the second signature is turned onto every segment from the heaviest point to another
  * point of the first (in 3D the rotation about that axis is then fixed by every pair of third
  * points), with and without mirroring. Each alignment is scored: every point of one signature
  * whose nearest neighbour (FLANN) in the other lies within the threshold adds
  * 1 - |w_p - w_q| / (w_p + w_q); every point of either signature without a partner subtracts its
  * weight. The paper's score is the best over all alignments, searched in both directions (moving
  * the first onto the second and the second onto the first), so match (a, b) == match (b, a).
  */
class PCL_EXPORTS SignatureMatcher
{
public:
  using Ptr = shared_ptr<SignatureMatcher>;
  using ConstPtr = shared_ptr<const SignatureMatcher>;

  /** \brief The comparison (for MatchMethod::Paper: the best alignment found). */
  struct Result
  {
    /** How similar the two signatures are, higher = more similar, 1 for identical ones: the key
      * databases rank by. Description methods: exp(-distance), in (0, 1]. Paper: paper_score over
      * the larger number of points (the raw score grows with the number of features), at most 1. */
    double similarity = 0.0;
    /** Description methods: the distance between the descriptions, >= 0, 0 for identical ones.
      * NaN for MatchMethod::Paper. */
    double distance = std::numeric_limits<double>::quiet_NaN ();
    /** MatchMethod::Paper: the paper's raw score of the best alignment, higher = more similar, at
      * most the larger number of points. NaN for the other methods. */
    double paper_score = std::numeric_limits<double>::quiet_NaN ();
    /** Paper: maps the second signature's (normalised) points onto the first's: x_a = linear * x_b +
      * translation; linear is a rotation, mirrored when its determinant is -1. Identity otherwise. */
    Eigen::Matrix3d linear = Eigen::Matrix3d::Identity ();
    Eigen::Vector3d translation = Eigen::Vector3d::Zero ();
    bool mirrored = false;
    /** Paper: matched pairs (index in the first signature, index in the second). */
    std::vector<std::pair<int, int>> pairs;
    std::size_t alignments = 0; ///< Paper: alignments scored
    /** Why nothing was matched (parameters that checkMatchParameters refuses, or a description
      * method and a signature without a description; similarity is then -infinity, distance and
      * paper_score NaN), or ok. */
    pcl_flowseg::Status status;
  };

  SignatureMatcher () = default;

  /** \brief All parameters at once (pcl_flowseg::MatchParameters; its defaults are the class's). */
  inline void setParameters (const pcl_flowseg::MatchParameters& params) { params_ = params; }
  inline const pcl_flowseg::MatchParameters& getParameters () const { return params_; }

  /** \brief pcl_flowseg::MatchParameters::method. */
  inline void setMethod (pcl_flowseg::MatchMethod method) { params_.method = method; }
  inline pcl_flowseg::MatchMethod getMethod () const { return params_.method; }

  /** \brief Compares \a a and \a b; match (a, b) == match (b, a). When either is a single-view
    * scan's (ViewSet::single_view), every method but the paper's aligns the scan with the other's
    * views and whole surface (or with the other scan): distance is the mean distance between the
    * aligned points, in RMS radii of the visible points, and infinite when the other has no views
    * (a 2D shape). Paper: empty signatures score 0
    * against empty ones and minus the other's total weight otherwise. Parameters that
    * checkMatchParameters refuses match nothing: Result::status says why. */
  Result match (const pcl_flowseg::Signature& a, const pcl_flowseg::Signature& b) const;

protected:
  /** The paper's comparison. */
  Result matchPaper (const pcl_flowseg::Signature& a, const pcl_flowseg::Signature& b) const;
  /** Best alignment moving \a b onto \a a, scored from b's points. */
  Result alignOnto (const pcl_flowseg::Signature& a, const pcl_flowseg::Signature& b) const;

  pcl_flowseg::MatchParameters params_;
};

} // namespace pcl

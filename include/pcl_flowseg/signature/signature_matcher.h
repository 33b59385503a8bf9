/*
 * pcl_flowseg - matching two signatures (paper, section 5): alignment search and score.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/status.h>
#include <pcl_flowseg/signature/match_method.h>
#include <pcl_flowseg/signature/signature.h>

#include <pcl/memory.h>
#include <pcl/pcl_macros.h>

#include <string>
#include <utility>
#include <vector>

namespace pcl_flowseg {

/** \brief How two signatures are compared. */
struct MatchParameters
{
  /** The comparison; the other parameters concern MatchMethod::Paper only. */
  MatchMethod method = MatchMethod::Combined;
  /** Largest distance between partner points, in the signatures' normalised length unit
    * (interior volume^(1/d); finite, > 0). */
  double threshold = 0.4;
  /** Also try mirrored alignments: mirror images match. */
  bool allow_mirror = true;
  /** How many of the heaviest points of each signature generate alignments (1..100; all points are
    * scored). The search costs O(m^2 n^2) alignments in 3D. */
  int alignment_points = 4;
};

/** \brief Why \a params cannot be used (a message naming the parameter), or success. */
Status
checkMatchParameters (const MatchParameters& params);

} // namespace pcl_flowseg

namespace pcl {

/** \brief Compares two shape signatures; invariant to translation, rotation, mirroring and scale.
  *
  * By default (pcl_flowseg::MatchMethod::Combined) and with the other description methods it
  * compares the signatures' shape descriptions: the distance d of the method (0 for identical
  * descriptions) gives the similarity exp(-d), in (0, 1]; nothing is aligned.
  *
  * MatchMethod::Paper is the paper's alignment search: the heaviest points of the two signatures are made to coincide,
  * then the segment from the heaviest point to another point of the second signature is turned
  * onto every segment from the heaviest point to another point of the first (in 3D the rotation
  * about that axis is then fixed by every pair of third points), with and without mirroring. Each
  * alignment is scored: every point of one signature whose nearest neighbour (FLANN) in the other
  * lies within the threshold adds 1 - |w_p - w_q| / (w_p + w_q); every point of either signature
  * without a partner subtracts its weight. The similarity is the best score over all alignments,
  * searched in both directions (moving the first onto the second and the second onto the first),
  * so match (a, b) == match (b, a).
  */
class PCL_EXPORTS SignatureMatcher
{
public:
  using Ptr = shared_ptr<SignatureMatcher>;
  using ConstPtr = shared_ptr<const SignatureMatcher>;

  /** \brief The comparison (for MatchMethod::Paper: the best alignment found). */
  struct Result
  {
    /** Paper: the paper's score, higher is more similar, at most the number of points. Other
      * methods: the distance between the descriptions (0 = identical). */
    double score = 0.0;
    /** Paper: score divided by the larger number of points, comparable across signatures of
      * different sizes (the raw score grows with the number of features). Other methods:
      * exp(-score). 1 for identical signatures; databases rank by it. */
    double similarity = 0.0;
    /** Paper: maps the second signature's (normalised) points onto the first's: x_a = linear * x_b +
      * translation; linear is a rotation, mirrored when its determinant is -1. Identity otherwise. */
    Eigen::Matrix3d linear = Eigen::Matrix3d::Identity ();
    Eigen::Vector3d translation = Eigen::Vector3d::Zero ();
    bool mirrored = false;
    /** Matched pairs (index in the first signature, index in the second). */
    std::vector<std::pair<int, int>> pairs;
    std::size_t alignments = 0; ///< alignments scored
    /** Why nothing was matched (parameters that checkMatchParameters refuses, or a description
      * method and a signature without a description; score and similarity are then -infinity), or ok. */
    pcl_flowseg::Status status;
  };

  SignatureMatcher () = default;

  /** \brief All parameters at once (pcl_flowseg::MatchParameters; its defaults are the class's). */
  inline void setParameters (const pcl_flowseg::MatchParameters& params) { params_ = params; }
  inline const pcl_flowseg::MatchParameters& getParameters () const { return params_; }

  /** \brief pcl_flowseg::MatchParameters::method. */
  inline void setMethod (pcl_flowseg::MatchMethod method) { params_.method = method; }
  inline pcl_flowseg::MatchMethod getMethod () const { return params_.method; }
  /** \brief pcl_flowseg::MatchParameters::threshold. */
  inline void setThreshold (double threshold) { params_.threshold = threshold; }
  inline double getThreshold () const { return params_.threshold; }
  /** \brief pcl_flowseg::MatchParameters::allow_mirror. */
  inline void setAllowMirror (bool allow) { params_.allow_mirror = allow; }
  inline bool getAllowMirror () const { return params_.allow_mirror; }
  /** \brief pcl_flowseg::MatchParameters::alignment_points. */
  inline void setAlignmentPoints (int count) { params_.alignment_points = count; }
  inline int getAlignmentPoints () const { return params_.alignment_points; }

  /** \brief Similarity of \a a and \a b; match (a, b) == match (b, a). Paper: empty signatures
    * score 0 against empty ones and minus the other's total weight otherwise. Parameters that checkMatchParameters refuses match nothing:
    * Result::status says why. */
  Result match (const pcl_flowseg::Signature& a, const pcl_flowseg::Signature& b) const;

protected:
  /** The paper's comparison. */
  Result matchPaper (const pcl_flowseg::Signature& a, const pcl_flowseg::Signature& b) const;
  /** Best alignment moving \a b onto \a a, scored from b's points. */
  Result alignOnto (const pcl_flowseg::Signature& a, const pcl_flowseg::Signature& b) const;

  pcl_flowseg::MatchParameters params_;
};

} // namespace pcl

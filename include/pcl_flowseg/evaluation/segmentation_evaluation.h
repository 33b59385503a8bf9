/*
 * pcl_flowseg - measuring segmentations against reference ones (Princeton Segmentation Benchmark).
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <pcl_flowseg/common/flow_result.h>
#include <pcl_flowseg/io/mesh_io.h>
#include <pcl_flowseg/common/status.h>

#include <Eigen/Core>

#include <cstdint>
#include <string>
#include <vector>

namespace pcl_flowseg {

/** \brief Reads a Princeton Segmentation Benchmark `.seg` file: one integer segment id per line,
  * one line per face, faces in the order of the mesh file. Blank lines (a trailing newline, say)
  * are ignored.
  * \param[in] path the file
  * \param[in] face_count number of faces of the mesh the segmentation belongs to
  * \param[out] labels one segment id per face; left empty on failure
  * \return ok, or why not: missing or unreadable file, a line that is not one integer (with its
  *         line number), or a number of ids other than \a face_count. */
Status
readFaceSegmentation (const std::string& path, std::size_t face_count, std::vector<int>& labels);

/** \brief Area of every face of \a mesh, in face order. */
std::vector<double>
faceAreas (const TriangleMesh& mesh);

/** \brief Weighted Rand-index error (1 - Rand index) between two labellings \a a and \a b of the
  * same elements: the weighted share of the pairs {i, j} of distinct elements (weight w_i w_j) that
  * one labelling puts in one segment and the other in two; 0 for identical partitions (whatever
  * the ids), up to 1. Computed from a contingency table (O(n), no loop over pairs). With unit
  * weights it is the PSB's own "RI" error over faces; with face areas it does not depend on how
  * finely a region is triangulated (docs/method.md has the formula and the comparison).
  * \param[in] weights non-negative weight of each element (face areas, or all 1)
  * \param[in] a, b labels of each element (any integers; only equality matters)
  * \param[out] error in [0, 1]; 0 when fewer than two elements (or all weight on one element)
  * \return success, or why not: the three vectors differ in length. */
Status
randIndexError (const std::vector<double>& weights, const std::vector<int>& a, const std::vector<int>& b, double& error);

/** \brief Label of each face of \a mesh taken from labelled sample points near it.
  *
  * Each face votes at four places: its centroid and the three points halfway from the centroid to
  * its corners. At each place the 4 nearest labelled points (FLANN k-d tree over the labelled
  * points only) give one vote each; the face takes the label with most of the 16 votes (ties: the
  * smaller label). Points labelled kNoSegment, or with a label listed in \a unlabelled, or with
  * non-finite coordinates, never vote: a face near them takes the label of the nearest labelled
  * points however far away those lie.
  *
  * \param[in] mesh the faces to label
  * \param[in] points sample points (any number, e.g. sampled on the mesh)
  * \param[in] point_labels one label per point (e.g. FlowResult::point_labels)
  * \param[out] face_labels one label per face; -1 for every face when no point is labelled
  * \param[in] unlabelled further labels that mean "no label"
  * \return success, or why not: \a points and \a point_labels differ in length. */
Status
transferPointLabelsToFaces (const TriangleMesh& mesh, const std::vector<Eigen::Vector3d>& points,
                            const std::vector<std::uint32_t>& point_labels, std::vector<int>& face_labels,
                            const std::vector<std::uint32_t>& unlabelled = {});

} // namespace pcl_flowseg

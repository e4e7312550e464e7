#pragma once
// What a materials scientist follows during a tensile test of a tube network (tensile.hpp):
// contacts, aligned pairs, bundles and orientation, from the contact neighbour list.
//  * contacts: pairs whose walls are closer than maxGap at the closest points of the axes;
//    aligned: those whose axes cross below maxAngle.
//  * bundles: connected groups of elements joined by aligned contacts (union-find over the
//    aligned pairs; an element in no aligned contact is no bundle). Reported: how many bundles,
//    the elements in them, the mean and the largest size.
//  * orientation: the 2-D orientation tensor Q = <u u^T> of the element axes projected on the
//    film plane (x-y; each projection normalised, vertical elements left out); order parameter
//    S = lambda1 - lambda2 (0 isotropic, 1 all parallel) and the alignment with the pulling axis
//    <cos 2 phi> = Q_aa - Q_bb (1: all along it, -1: all across).
#include "mdem/contacts/contact_effects.hpp"

namespace mesochain::mdem {

struct NetworkStructure {
  int contacts = 0, aligned = 0;
  int bundles = 0, elementsInBundles = 0, largestBundle = 0;
  double meanBundle = 0.0;       // elements per bundle
  double orderParameter = 0.0;   // S
  double axisAlignment = 0.0;    // <cos 2 phi> about `axis`
};

NetworkStructure networkStructure(const ContactNeighbourhood& nb, const Bodies& b, double maxGap, double maxAngle,
                                  int axis);

}  // namespace mesochain::mdem

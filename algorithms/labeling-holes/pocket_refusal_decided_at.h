// Step 8's early stop (open_pockets_closed_at_their_mouths.h): whether the tests after a walk
// from a mouth will refuse its pocket whatever the walk still adds, read at one sample.
//
// Where in-the-pocket and the rest alternate four times or more around the sample, it will
// have that many boundary edges (the boundary test wants at most two); where inner-outside
// (inner and out of the pocket) and the rest alternate four times or more and a vertex of its
// fan is in the pocket, it will have that many curve edges once the pocket opens (the samples
// test wants two or none). The vertices decided later go in between the decided ones, and
// inserting elements into a cyclic sequence never lowers its number of alternations.
//
// In:  Delaunay/Voronoi arrays; `decided(t)`, how the walk has decided Voronoi vertex t so far
//      (t may be kInfinite); a sample with a cell.
// Out: true if the decided vertices of the sample's fan, in cyclic order (a hull sample's
//      infinite vertex one of them, which `decided` must call outer), show one of the two
//      alternations.
#pragma once

#include <cstdint>

#include "voronoi/delaunay_voronoi.h"

namespace curvebench {

// How a walk from a mouth has decided a Voronoi vertex so far: in the pocket, or out of it for
// good (outer, the infinite vertex included; inner and stopped, or inner where the walk never
// goes). A vertex the walk may still reach is not decided yet.
enum class PocketVertex : std::uint8_t { kNotDecided, kInPocket, kOuter, kInnerOutside };

template <class Decided>
bool pocket_refusal_decided_at(const DelaunayVoronoi& dv, Decided&& decided, int site) {
  int first_in = -1, first_outside = -1, last_in = -1, last_outside = -1;
  int in_alternations = 0, outside_alternations = 0;
  bool fan_in_pocket = false;
  auto add = [&](PocketVertex d) {
    if (d == PocketVertex::kNotDecided) return;
    const int in = d == PocketVertex::kInPocket, outside = d == PocketVertex::kInnerOutside;
    fan_in_pocket = fan_in_pocket || in;
    if (first_in < 0) {
      first_in = in;
      first_outside = outside;
    } else {
      in_alternations += in != last_in;
      outside_alternations += outside != last_outside;
    }
    last_in = in;
    last_outside = outside;
  };
  for_each_voronoi_vertex_around(dv, site, [&](int t) { add(decided(t)); });
  if (first_in >= 0) {  // the cycle closes
    in_alternations += last_in != first_in;
    outside_alternations += last_outside != first_outside;
  }
  return in_alternations >= 4 || (fan_in_pocket && outside_alternations >= 4);
}

}  // namespace curvebench

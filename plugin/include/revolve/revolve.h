// revolve: surfaces of revolution traced exactly, alone or inside Embree 3 or 4.
//
// The one include for users: revolve/core.h (profiles, splines, shapes and their exact queries,
// shading normals, clearance, inside the solid; no Embree needed) and revolve/embree.h (the Embree
// user geometry, point queries over scenes). Link revolve::revolve; a program that needs no Embree
// may include revolve/core.h alone and link revolve::core. The comparisons of benchmarks, not
// needed to trace anything, have headers of their own: revolve/baselines.h (the MIBIT paper's
// searches and switches) and revolve/embree_baselines.h (a tessellated mesh, Embree's cone curve).
#pragma once

#include <revolve/core.h>
#include <revolve/embree.h>

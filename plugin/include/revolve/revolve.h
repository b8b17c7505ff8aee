// revolve: surfaces of revolution traced exactly, alone or inside Embree 3 or 4.
//
// The one include for users: revolve/core.h (profiles, splines, shapes and their exact queries,
// shading normals, clearance; no Embree needed) and revolve/embree.h (the Embree user geometry,
// point queries over scenes, meshes and cone curves for comparison). Link revolve::revolve; a
// program that needs no Embree may include revolve/core.h alone and link revolve::core.
#pragma once

#include <revolve/core.h>
#include <revolve/embree.h>

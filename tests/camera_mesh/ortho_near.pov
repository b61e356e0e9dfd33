// The reference of dist1_near.scn: the orthographic camera of ortho.pov on a
// world clipped at the mesh camera's max_distance from the camera's plane
// (world.inc; Place in grid.inc is the same rotate and translate).
#declare Near = 10.5;
#include "ortho.pov"

// The reference of the distribution 0 case, whose rays leave their faces
// 0.5 forward: a ray from below the floor that starts above it sees it.
#declare Forward = 0.5;
#include "ortho.pov"

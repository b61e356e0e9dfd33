// The reference of the distribution 0, 1 and 3 cases: the orthographic
// camera that makes the same rays (from Forward along them, default 0).
#include "world.inc"
#include "grid.inc"
#ifndef (Forward) #declare Forward = 0; #end
camera { orthographic location z * Forward direction z right x * 8 up y * 6 transform { Place } }

#declare PointLight = 1;
#include "caustic.pov"

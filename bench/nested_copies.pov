// Memory of nested copies of declared objects (bench/README.md): 8^4 copies of a three-shape
// union, four levels deep, 12,288 shapes in all.
#version 3.7;
camera { location <0,2,-6> look_at 0 }
light_source { <5,10,-5> rgb 1 }
#declare L0 = union { sphere { 0, 0.1 pigment { rgb <1,0.5,0.2> } } cylinder { 0, y*0.2, 0.03 pigment { rgb 1 } } box { -0.05, 0.05 translate x*0.1 } }
#declare L1 = union { #for (i,0,7) object { L0 translate <mod(i,4)-1.5, 0, div(i,4)-0.5>*0.3 } #end }
#declare L2 = union { #for (i,0,7) object { L1 translate <mod(i,4)-1.5, 0, div(i,4)-0.5>*1.3 scale 0.5 } #end }
#declare L3 = union { #for (i,0,7) object { L2 translate <mod(i,4)-1.5, 0, div(i,4)-0.5>*3 scale 0.5 } #end }
#declare L4 = union { #for (i,0,7) object { L3 translate <mod(i,4)-1.5, 0, div(i,4)-0.5>*6 scale 0.5 } #end }
object { L4 }

#version 3.7;
camera { location -5*z look_at 0 }
prism { 0, 1, 65537, @@<0,0>, @@<1,1> pigment { rgb 1 } }

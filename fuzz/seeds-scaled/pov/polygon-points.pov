#version 3.7;
camera { location -5*z look_at 0 }
polygon { 65537, @@<0,0,0>, @@<1,1,0> pigment { rgb 1 } }

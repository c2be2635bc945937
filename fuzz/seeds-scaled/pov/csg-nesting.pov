#version 3.7;
camera { location -5*z look_at 0 }
@@difference { sphere { 0, 1 } @@sphere { x, 1 }@@ }@@

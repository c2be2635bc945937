#version 3.7;
camera { location -5*z look_at 0 }
@@union { @@sphere { 0, 1 }@@ }@@

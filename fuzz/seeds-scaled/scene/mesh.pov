camera { location <0,0,14> up <0,1,0> right <1.33,0,0> look_at <0,0,0> }
mesh { @@triangle { <0,0,0>, <1,0,0>, <0,1,0> }
@@}

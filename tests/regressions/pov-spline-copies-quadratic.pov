#declare S = spline { linear_spline 0, <0, 0, 0> }
#for (I, 1, 19000) #declare S = spline { S I, <I, 0, 0> } #end

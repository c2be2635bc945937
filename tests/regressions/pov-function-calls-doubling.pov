#declare F = function { x + 1 }
#for (I, 0, 40) #declare F = function { F(x, y, z) + F(y, x, z) } #end
#declare A = F(1, 2, 3);

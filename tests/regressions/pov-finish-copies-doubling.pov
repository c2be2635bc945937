#declare F = finish { ambient 0.1 }
#for (I, 0, 40) #declare F = finish { F F } #end
sphere { 0, 1 finish { F } }

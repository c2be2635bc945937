#declare T = transform { rotate x }
#for (I, 0, 40) #declare T = transform { transform { T } transform { T } } #end
sphere { 0, 1 transform { T } }

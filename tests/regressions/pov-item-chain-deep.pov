#declare O = sphere { 0, 1 }
#for (I, 0, 19999) #declare O = union { object { O } } #end

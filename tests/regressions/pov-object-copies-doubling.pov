#declare O = sphere { 0, 1 }
#for (I, 0, 40) #declare O = union { object { O } object { O translate x } } #end
object { O }

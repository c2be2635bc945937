#declare M = mesh { triangle { 0, x, y } triangle { 0, y, z } }
#for (I, 0, 40) #declare M = union { object { M } object { M translate x } } #end
object { M }

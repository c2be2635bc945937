#declare S = "ab";
#for (I, 1, 22) #declare S = concat(S, S); #end
#declare A = array[300];
#for (I, 0, 299) #declare A[I] = concat(S, S); #end

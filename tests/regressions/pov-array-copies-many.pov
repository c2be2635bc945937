#declare B = array[300000];
#declare A = array[100];
#for (I, 0, 99) #declare A[I] = B; #end

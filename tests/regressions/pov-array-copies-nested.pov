#declare A = array[1];
#declare A[0] = 1;
#for (I, 0, 19000) #declare B = array[1]; #declare B[0] = A; #declare A = B; #end

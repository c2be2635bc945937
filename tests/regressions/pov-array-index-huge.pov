#declare A = array[2];
#declare A[1e300] = 1;

#declare S = "ab";
#for (I, 1, 22) #declare S = concat(S, S); #end
#fopen F "big.txt" write
#for (I, 0, 999) #write (F, S) #end

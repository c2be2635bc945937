#for (I, 0, 19990) #default { finish { ambient 0.1 } } #end
sphere { 0, 1 }

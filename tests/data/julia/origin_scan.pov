#version 3.7;
#declare J = julia_fractal { CC quaternion sqr max_iteration MI precision PR }
#fopen F "out.txt" write
#declare D=<0,0,1>;
#for (k,K0,K1)
  #declare O=<BB,0,k*STP>;
  #declare Nrm=<0,0,0>;
  #declare H=trace(J,O,D,Nrm);
  #write (F, k*STP, ",", H.z, ",", vlength(Nrm),"\n")
#end
#fclose F

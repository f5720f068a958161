MODULE Collide ;
(* One fixed scene: when do the two circles touch? (See ../README.md for the scene.) *)
FROM STextIO IMPORT WriteString, WriteLn ;
FROM SRealIO IMPORT WriteFloat ;
FROM circles IMPORT Params, FirstRootNamed ;

VAR
   q: Params ;
   t: REAL ;
BEGIN
   (* The parameters by name (circles.Params); FirstRoot takes them as an array. *)
   q.x1 := 0.0 ; q.y1 := 0.0 ; q.vx1 := 1.0 ; q.vy1 := 0.0 ; q.ax1 := 0.5 ; q.ay1 := 0.0 ;
   q.r1 := 1.0 ;
   q.x2 := 10.0 ; q.y2 := 0.0 ; q.vx2 := -1.0 ; q.vy2 := 0.0 ; q.ax2 := 0.0 ; q.ay2 := 0.0 ;
   q.r2 := 0.5 ;
   IF FirstRootNamed(q, 100.0, t) THEN
      WriteString("collision at t = ") ; WriteFloat(t, 17, 1) ; WriteLn
   ELSE
      WriteString("no collision") ; WriteLn ;
      HALT(1)
   END
END Collide.

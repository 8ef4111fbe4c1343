C     Bratu's problem u'' + lambda exp(u) = 0, u(0) = u(1) = 0, in the old
C     style: the routines the run calls declare their arguments through
C     IMPLICIT DOUBLE PRECISION; FOPT and PVLS are stubs that keep
C     Fortran's implicit typing (U, PAR, FS, DFDU, DFDP REAL), as AUTO
C     accepts them: FOPT is never called for this problem, and PVLS is called
C     but never looks at its arguments.
      SUBROUTINE FUNC(NDIM,U,ICP,PAR,IJAC,F,DFDU,DFDP)
      IMPLICIT DOUBLE PRECISION (A-H,O-Z)
      DIMENSION U(NDIM), PAR(*), F(NDIM), DFDU(NDIM,*), DFDP(NDIM,*)
      F(1) = U(2)
      F(2) = -PAR(1)*EXP(U(1))
      RETURN
      END

      SUBROUTINE STPNT(NDIM,U,PAR,T)
      IMPLICIT DOUBLE PRECISION (A-H,O-Z)
      DIMENSION U(NDIM), PAR(*)
      PAR(1) = 0.0D0
      U(1) = 0.0D0
      U(2) = 0.0D0
      RETURN
      END

      SUBROUTINE BCND(NDIM,PAR,ICP,NBC,U0,U1,FB,IJAC,DBC)
      IMPLICIT DOUBLE PRECISION (A-H,O-Z)
      DIMENSION PAR(*), U0(NDIM), U1(NDIM), FB(NBC), DBC(NBC,*)
      FB(1) = U0(1)
      FB(2) = U1(1)
      RETURN
      END

      SUBROUTINE ICND(NDIM,PAR,ICP,NINT,U,UOLD,UDOT,UPOLD,FI,IJAC,DINT)
      RETURN
      END

      SUBROUTINE FOPT(NDIM,U,ICP,PAR,IJAC,FS,DFDU,DFDP)
      RETURN
      END

      SUBROUTINE PVLS(NDIM,U,PAR)
      RETURN
      END

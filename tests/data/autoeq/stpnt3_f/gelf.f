C     Gelfand's problem on half the interval: u'' + lambda exp(u) = 0 with
C     u'(0) = 0, u(1) = 0 (Bratu's problem on [-1, 1], folded at its centre),
C     whose fold is at lambda = 3.51383071912516/4.  STPNT has the legacy
C     three arguments STPNT(NDIM,U,PAR) of AUTO's older versions: the start
C     u = 0 does not depend on t, and AUTO-07p, which passes T as well,
C     runs it.
      SUBROUTINE FUNC(NDIM,U,ICP,PAR,IJAC,F,DFDU,DFDP)
      IMPLICIT DOUBLE PRECISION (A-H,O-Z)
      DIMENSION U(NDIM), PAR(*), F(NDIM), DFDU(NDIM,*), DFDP(NDIM,*)
      F(1) = U(2)
      F(2) = -PAR(1)*EXP(U(1))
      RETURN
      END

      SUBROUTINE STPNT(NDIM,U,PAR)
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
      FB(1) = U0(2)
      FB(2) = U1(1)
      RETURN
      END

      SUBROUTINE ICND
      END

      SUBROUTINE FOPT
      END

      SUBROUTINE PVLS
      END

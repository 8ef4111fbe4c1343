! The planar elastica with its centre line in the complex plane: the state is
! declared COMPLEX, as AUTO accepts it (AUTO passes U as NDIM DOUBLE
! PRECISION numbers, which a COMPLEX(KIND(1.0D0)) array of NDIM/2 elements
! reads as (re, im) pairs).
!   U(1) = theta + i theta'     theta'' + P sin(theta) = 0
!   U(2) = x + i y              (x + i y)' = exp(i theta)
! theta'(0) = theta'(1) = 0, x(0) = y(0) = 0; PAR(1) = P.  The straight rod
! theta = 0, x + i y = t solves it for every P; its branch points are at
! P = (n pi)**2 (the linearisation theta'' + P theta = 0).
SUBROUTINE FUNC(NDIM,U,ICP,PAR,IJAC,F,DFDU,DFDP)
  IMPLICIT NONE
  INTEGER, INTENT(IN) :: NDIM, ICP(*), IJAC
  COMPLEX(KIND(1.0D0)), INTENT(IN) :: U(NDIM/2)
  DOUBLE PRECISION, INTENT(IN) :: PAR(*)
  COMPLEX(KIND(1.0D0)), INTENT(OUT) :: F(NDIM/2)
  DOUBLE PRECISION, INTENT(INOUT) :: DFDU(NDIM,NDIM), DFDP(NDIM,*)
  DOUBLE PRECISION THETA
  THETA = DBLE(U(1))
  F(1) = CMPLX(AIMAG(U(1)), -PAR(1)*SIN(THETA), KIND(1.0D0))
  F(2) = EXP(CMPLX(0.0D0, THETA, KIND(1.0D0)))
END SUBROUTINE FUNC

SUBROUTINE STPNT(NDIM,U,PAR,T)
  IMPLICIT NONE
  INTEGER, INTENT(IN) :: NDIM
  COMPLEX(KIND(1.0D0)), INTENT(INOUT) :: U(NDIM/2)
  DOUBLE PRECISION, INTENT(INOUT) :: PAR(*)
  DOUBLE PRECISION, INTENT(IN) :: T
  PAR(1) = 1.0D0
  U(1) = (0.0D0, 0.0D0)
  U(2) = CMPLX(T, 0.0D0, KIND(1.0D0))
END SUBROUTINE STPNT

SUBROUTINE BCND(NDIM,PAR,ICP,NBC,U0,U1,FB,IJAC,DBC)
  IMPLICIT NONE
  INTEGER, INTENT(IN) :: NDIM, ICP(*), NBC, IJAC
  DOUBLE PRECISION, INTENT(IN) :: PAR(*)
  COMPLEX(KIND(1.0D0)), INTENT(IN) :: U0(NDIM/2), U1(NDIM/2)
  DOUBLE PRECISION, INTENT(OUT) :: FB(NBC)
  DOUBLE PRECISION, INTENT(INOUT) :: DBC(NBC,*)
  FB(1) = AIMAG(U0(1))
  FB(2) = AIMAG(U1(1))
  FB(3) = DBLE(U0(2))
  FB(4) = AIMAG(U0(2))
END SUBROUTINE BCND

SUBROUTINE ICND
END SUBROUTINE ICND

SUBROUTINE FOPT
END SUBROUTINE FOPT

SUBROUTINE PVLS
END SUBROUTINE PVLS

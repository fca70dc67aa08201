#!/usr/bin/env bash
# tests/mpi_test.sh CDREF CDREF_MPI MPIRUN - campaigns across MPI ranks on this machine:
#  - 1, 2 and 4 ranks print byte for byte what one process prints (text form, JSON, CSV, table);
#  - a rank lost mid-run (it kills itself after a checkpoint: CDREF_MPI_TEST_KILL_RANKS), the
#    job resumed (with another number of ranks, and a rank lost again): exactly the
#    uninterrupted result, nothing counted twice;
#  - the whole job lost, resumed on one rank, then resumed once more when all was done;
#  - errors by name: a bad option, --resume without a checkpoint, another campaign's checkpoint.
set -euo pipefail
cdref="$1"
cdref_mpi="$2"
mpirun="$3"
dir=$(mktemp -d)
trap 'kill -9 $(jobs -p) 2>/dev/null || true; rm -rf "$dir"' EXIT
cd "$dir"
fail() {  # the reason, then what the background jobs said
  echo "FAIL: $*" >&2
  for f in *.err; do [ -s "$f" ] && { echo "--- $f:" >&2; tail -n 20 "$f" >&2; }; done
  exit 1
}
# OpenMPI refuses root unless told twice (CI runs as root); --oversubscribe: 4 ranks on 2 cores;
# no grace period between the TERM and the KILL of a failed job's other ranks (2 s by default)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpi() { local np=$1; shift; "$mpirun" --oversubscribe --mca odls_base_sigkill_timeout 0 -np "$np" "$cdref_mpi" "$@"; }

args=(campaign --query segment-sphere-cast --query box-box --query ray-triangle-cast
      --family long-range --family degenerate --impl book-float --impl book-double --impl robust-double
      --n 1500 --seed 11)
"$cdref" "${args[@]}" --threads 2 --out ref.txt --json ref.json --csv ref.csv > ref.tbl
head -n -2 ref.tbl > ref.table  # (the last line: the time taken)

same() {  # same RUN: RUN's outputs are the single process's, byte for byte
  cmp -s ref.txt "$1.txt" || fail "$1: the text form differs: $(diff ref.txt "$1.txt" | head -5)"
  cmp -s ref.json "$1.json" || fail "$1: the JSON differs"
  cmp -s ref.csv "$1.csv" || fail "$1: the CSV differs"
  head -n -2 "$1.tbl" > "$1.table"
  cmp -s ref.table "$1.table" || fail "$1: the table differs: $(diff ref.table "$1.table" | head -5)"
}
outs() { echo --out "$1.txt" --json "$1.json" --csv "$1.csv"; }

for np in 1 2 4; do
  mpi $np "${args[@]}" --threads 1 --checkpoint ck$np $(outs np$np) > np$np.tbl
  same np$np
  grep -q "on $np ranks of 1 threads" np$np.tbl || fail "np $np: $(tail -1 np$np.tbl)"
done

# a job whose ranks RANKS (r[,r...]) kill themselves with SIGKILL right after their first
# checkpoint written while working (cdref-mpi's CDREF_MPI_TEST_KILL_RANKS): a rank lost mid-run,
# whatever this machine's speed (a rank that no work reached, the others having finished it
# first, dies after its last checkpoint). The job must fail and leave FILE behind.
mpi_killed() {  # mpi_killed NP RANKS FILE ARGS...
  local np=$1 ranks=$2 file=$3; shift 3
  if CDREF_MPI_TEST_KILL_RANKS=$ranks "$mpirun" --oversubscribe --mca odls_base_sigkill_timeout 0 \
      -x CDREF_MPI_TEST_KILL_RANKS -np "$np" "$cdref_mpi" "$@" > killed.tbl 2> killed.err; then
    fail "the job finished although ranks $ranks were to die"
  fi
  [ -e "$file" ] || fail "no checkpoint $file after ranks $ranks died: $(ls)"
}

# rank 2 lost in generation 1 (4 ranks), rank 1 lost in generation 2 (2 ranks), then the rest
# on 4 ranks; every item counted once
mpi_killed 4 2 ck.g1.r2 "${args[@]}" --threads 1 --checkpoint ck --checkpoint-every 0 $(outs k)
mpi_killed 2 1 ck.g2.r1 "${args[@]}" --threads 1 --checkpoint ck --checkpoint-every 0 --resume $(outs k)
grep -q "^generation 2$" ck || fail "the resumed job did not open generation 2: $(cat ck)"
mpi 4 "${args[@]}" --threads 1 --checkpoint ck --checkpoint-every 0 --resume $(outs k) > k.tbl
same k
[ ! -e ck.g1.r0 ] && [ ! -e ck.g2.r0 ] || fail "earlier generations left behind: $(ls)"

# the whole job lost (every rank, rank 0 too), resumed on one rank, resumed again when done
mpi_killed 2 0,1 ca.g1.r0 "${args[@]}" --threads 1 --checkpoint ca --checkpoint-every 0 $(outs a)
mpi 1 "${args[@]}" --threads 2 --checkpoint ca --resume $(outs a) > a.tbl
same a
mpi 2 "${args[@]}" --threads 1 --checkpoint ca --resume $(outs a2) > a2.tbl
same a2

# errors by name, exit status 2, nothing written
expect_error() {  # expect_error PATTERN ARGS...: the job fails naming PATTERN
  local pat=$1; shift
  set +e
  mpi 2 "$@" > e.out 2> e.err
  local status=$?
  set -e
  [ $status -ne 0 ] || fail "'$*' succeeded"
  grep -q -- "$pat" e.err || fail "'$*': no '$pat' in: $(cat e.err)"
}
expect_error "not expected: --bogus" "${args[@]}" --bogus
expect_error "--resume needs --checkpoint FILE" "${args[@]}" --resume
expect_error "--impl book-float is given twice" "${args[@]}" --impl book-float
expect_error "not expected: describe" describe
expect_error "cannot resume: no checkpoint nothere" "${args[@]}" --checkpoint nothere --resume
other=("${args[@]}")
for k in "${!other[@]}"; do [ "${other[$k]}" = 11 ] && [ "${other[$((k - 1))]}" = --seed ] && other[$k]=12; done
expect_error "belongs to another campaign" "${other[@]}" --checkpoint ck --resume
"$cdref" "${args[@]}" --checkpoint single > /dev/null
expect_error "not a cdref-mpi checkpoint" "${args[@]}" --checkpoint single --resume
echo "mpi: identical at 1, 2 and 4 ranks, after lost ranks and a lost job"

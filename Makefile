# latticekit: the two commands of the README, and a few helpers.
.PHONY: demo test bench setup build clean

# The main job on the bundled CT head. The head's NIfTI header carries no
# orientation (it is stored head-down), so the camera is set for it here.
DEMO_INPUT ?= sample_data/cthead/cthead_hu_approx.nii.gz
DEMO_OUTPUT ?= latticekit-output
DEMO_VIEW ?= --view-from -0.5,-1,0 --view-up 0,0,-1

demo: setup
	xvfb-run -a build/bin/latticekit-demo $(DEMO_INPUT) -o $(DEMO_OUTPUT) $(DEMO_VIEW)

test: setup
	cd build && ctest --output-on-failure -j 2

bench: setup
	build/bin/bench_metro sample_data
	build/bin/bench_lattice sample_data
	build/bin/bench_fit sample_data
	build/bin/bench_subdivision sample_data
	build/bin/bench_ifs
	build/bin/bench_osteotomy sample_data

setup build:
	bash scripts/setup.sh

clean:
	rm -rf build $(DEMO_OUTPUT)

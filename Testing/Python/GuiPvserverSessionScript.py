"""The GUI client's part of GuiPvserverSession.py, run by
`paraview --server-url=cs://localhost:PORT --script=GuiPvserverSessionScript.py`: the session of
PvserverSessionPipeline.py built through the GUI's proxies on the connected pvserver, the
region shown in the GUI's render view and saved as a screenshot, the measurements written to
$BOOLSURF_GUI_RESULT (JSON). Closes the GUI at the end (exit code 0, or 1 on any error).
"""
import json
import os
import sys
import traceback

# Run by the GUI as a string: no __file__.
sys.path.insert(0, os.path.join(os.environ["BOOLSURF_SOURCE_DIR"], "Testing", "Python"))


def main():
    from paraview import servermanager as sm
    if not sm.ActiveConnection.IsRemote():
        raise RuntimeError("the GUI is not connected to a pvserver")
    import PvserverSessionPipeline as pipeline
    result_path = os.environ["BOOLSURF_GUI_RESULT"]
    folder = os.path.join(os.path.dirname(result_path), "gui")
    os.makedirs(folder, exist_ok=True)
    result = pipeline.run_session(folder)
    with open(result_path, "w") as f:
        json.dump(result, f, indent=1, sort_keys=True)
    sys.__stdout__.write("GUI session done on %d ranks\n" % result["ranks"])


try:
    main()
    code = 0
except Exception:
    # In the GUI, sys.stderr is the Output Messages window: also write to the terminal.
    traceback.print_exc(file=sys.__stderr__)
    code = 1
sys.stdout.flush()
sys.stderr.flush()
sys.__stdout__.flush()
sys.__stderr__.flush()
os._exit(code)  # close the GUI: ParaView would otherwise wait for the user

// The browser build's data folder (progress.json and ghosts/, docs/web.md) lives in the
// page's IndexedDB, so that best times and ghosts outlast a reload. Linked with --pre-js: this runs
// inside the module, where FS, IDBFS, ENV and the run dependencies are in scope.
//  - Before main: IDBFS is mounted at /persistent, XDG_DATA_HOME points there (so the game's
//    data_dir_from_env finds /persistent/soft-tire, as natively), and what IndexedDB holds is read
//    in; main waits for it (a run dependency).
//  - After the game writes there (web_page.h, persist_data): tirePersistData copies the folder back
//    to IndexedDB in the background, one copy at a time; #summary's data-persisted counts the copies
//    stored, which the web test waits for.
var tireDataFolder = '/persistent';
var tirePersistState = { busy: false, again: false, stored: 0 };

function tirePersistData() {
  if (tirePersistState.busy) {
    tirePersistState.again = true;  // once this copy is done, copy again
    return;
  }
  tirePersistState.busy = true;
  FS.syncfs(false, function (error) {
    tirePersistState.busy = false;
    if (error) {
      err('tire-game: could not save the progress to IndexedDB: ' + error);
    } else {
      tirePersistState.stored += 1;
      var summary = document.getElementById('summary');
      if (summary) summary.dataset.persisted = String(tirePersistState.stored);
    }
    if (tirePersistState.again) {
      tirePersistState.again = false;
      tirePersistData();
    }
  });
}

Module['preRun'] = Module['preRun'] || [];
if (typeof Module['preRun'] == 'function') Module['preRun'] = [Module['preRun']];
Module['preRun'].push(function () {
  FS.mkdir(tireDataFolder);
  FS.mount(IDBFS, {}, tireDataFolder);
  ENV['XDG_DATA_HOME'] = tireDataFolder;
  addRunDependency('tire-data-folder');
  FS.syncfs(true, function (error) {
    if (error) err('tire-game: could not read the saved progress from IndexedDB: ' + error);
    removeRunDependency('tire-data-folder');
  });
});

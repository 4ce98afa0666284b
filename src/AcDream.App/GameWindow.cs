using System.Numerics;
using AcDream.App.Streaming;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using Environment = AcDream.Core.Dat.Environment;

namespace AcDream.App;

/// <summary>
/// The headless client window: owns the <see cref="PhysicsEngine"/>, the region's height table and
/// the streaming state. A background loader thread reads landblocks from an
/// <see cref="ILandblockSource"/>; the frame loop calls <see cref="UpdateStreaming"/> once per frame,
/// which drains finished loads into the engine, unloads landblocks the observer left behind and
/// requests the ones it approaches.
/// </summary>
/// <remarks>
/// The streaming window is the square of landblocks within <see cref="StreamingRadius"/> of the
/// observer's landblock (3 × 3), clipped to the world. The engine is touched only by the frame
/// thread; the loader thread only reads from the source. The two share only the request and result
/// queues, under a lock that no callback runs inside. A cell or an object (of the landblock's
/// <see cref="LandBlockInfo"/> or a cell's static objects) that cannot be built is skipped with
/// a warning; a landblock that cannot be built at all is not registered (the engine never holds half
/// of one), is reported, and is requested again <see cref="RetryDelayFrames"/> frames later.
/// </remarks>
public sealed class GameWindow : IDisposable
{
    /// <summary>Landblocks kept loaded on each side of the observer's: 1, a 3 × 3 square.</summary>
    public const int StreamingRadius = 1;

    /// <summary>Frames (<see cref="UpdateStreaming"/> calls) before a failed landblock is requested again: 30, one second at 30 Hz.</summary>
    public const int RetryDelayFrames = 30;

    private readonly ILandblockSource _source;
    private readonly float[] _heightTable;
    private readonly Action<string> _log;

    // Guarded by _streamingLock: the loader's inbox and outbox, and what is in flight.
    private readonly object _streamingLock = new();
    private readonly Queue<uint> _requests = new();
    private readonly Queue<(uint Id, LoadedLandblock? Loaded, string? Error)> _completed = new();
    private readonly HashSet<uint> _pending = [];
    private bool _stopping;

    // Frame thread only.
    private readonly HashSet<uint> _window = [];
    private readonly HashSet<uint> _loaded = [];
    private readonly Dictionary<uint, long> _retryAtFrame = [];
    private readonly Dictionary<uint, int> _objectCounts = [];
    private readonly Thread _loader;
    private long _frame;

    /// <summary>
    /// Creates the window and starts its loader thread. Nothing is loaded until the first
    /// <see cref="UpdateStreaming"/>.
    /// </summary>
    /// <param name="source">Where landblocks come from; called on the loader thread.</param>
    /// <param name="heightTable">The region's 256 heights in metres (<c>LandHeightTable</c>); copied.</param>
    /// <param name="centerLandblockId">The landblock whose south-west corner is world (0, 0), <c>0xXXYYFFFF</c>.</param>
    /// <param name="log">Receives warnings and load failures, one line each; null to discard them.</param>
    /// <exception cref="ArgumentException">The table does not have 256 finite entries, or the id is not a landblock of the world.</exception>
    public GameWindow(ILandblockSource source, float[] heightTable, uint centerLandblockId, Action<string>? log = null)
    {
        ArgumentNullException.ThrowIfNull(source);
        ArgumentNullException.ThrowIfNull(heightTable);
        if (heightTable.Length != 256 || Array.Exists(heightTable, h => !float.IsFinite(h)))
        {
            throw new ArgumentException($"the height table must have 256 finite heights; it has {heightTable.Length} entries.", nameof(heightTable));
        }

        Physics = new PhysicsEngine(centerLandblockId);
        _source = source;
        _heightTable = (float[])heightTable.Clone();
        _log = log ?? (_ => { });
        _loader = new Thread(LoaderLoop) { IsBackground = true, Name = "landblock loader" };
        _loader.Start();
    }

    /// <summary>Raised on the frame thread after a landblock (<c>0xXXYYFFFF</c>) is registered in the engine.</summary>
    public event Action<uint>? LandblockLoaded;

    /// <summary>Raised on the frame thread after a landblock (<c>0xXXYYFFFF</c>) is removed from the engine.</summary>
    public event Action<uint>? LandblockUnloaded;

    /// <summary>The engine, in the world frame of the centre landblock (metres; world (0, 0) is its south-west corner).</summary>
    public PhysicsEngine Physics { get; }

    /// <summary>The landblocks (<c>0xXXYYFFFF</c>) registered in the engine. Frame thread only.</summary>
    public IReadOnlyCollection<uint> LoadedLandblocks => _loaded;

    /// <summary>The landblocks (<c>0xXXYYFFFF</c>) the streaming window wants, as of the last <see cref="UpdateStreaming"/>. Frame thread only.</summary>
    public IReadOnlyCollection<uint> WindowLandblocks => _window;

    /// <summary>
    /// The landblock (<c>0xXXYYFFFF</c>) under a world position; positions off the world (however far,
    /// infinities included) clamp to the nearest edge landblock. The engine's
    /// <see cref="PhysicsEngine.LandblockAt"/>.
    /// </summary>
    /// <param name="worldPosition">World metres (Z is ignored).</param>
    /// <exception cref="ArgumentException">X or Y is NaN.</exception>
    public uint LandblockAt(Vector3 worldPosition) => Physics.LandblockAt(worldPosition);

    /// <summary>
    /// The frame loop's streaming step: moves the window to the observer, registers the loads that
    /// finished (those still in the window), unloads landblocks outside the window, drops the queued
    /// requests that left it, and requests the missing ones; the loader takes the queue nearest first
    /// (by distance to the observer's landblock). Never blocks on a load.
    /// </summary>
    /// <remarks>
    /// <see cref="LandblockLoaded"/>, <see cref="LandblockUnloaded"/> and the log run on this thread
    /// with the streaming lock released, so they may call <see cref="Dispose"/>. After
    /// <see cref="Dispose"/> this still registers what finished and unloads, but requests nothing.
    /// </remarks>
    /// <param name="observerWorldPosition">The observer (the player), world metres.</param>
    /// <exception cref="ArgumentException">The observer's X or Y is NaN.</exception>
    public void UpdateStreaming(Vector3 observerWorldPosition)
    {
        uint center = LandblockAt(observerWorldPosition);
        _frame++;
        int cx = CellIds.LandblockX(center), cy = CellIds.LandblockY(center);
        _window.Clear();
        for (int dx = -StreamingRadius; dx <= StreamingRadius; dx++)
        {
            for (int dy = -StreamingRadius; dy <= StreamingRadius; dy++)
            {
                int x = cx + dx, y = cy + dy;
                if (x >= 0 && y >= 0 && x <= PhysicsConstants.MaxLandblockIndex && y <= PhysicsConstants.MaxLandblockIndex)
                {
                    _window.Add(CellIds.Landblock(x, y));
                }
            }
        }

        // Only the hand-over queues need the lock; the engine and the callbacks run without it.
        List<(uint Id, LoadedLandblock? Loaded, string? Error)> finished;
        lock (_streamingLock)
        {
            finished = [.. _completed];
            _completed.Clear();
            foreach ((uint id, _, _) in finished)
            {
                _pending.Remove(id);
            }
        }

        foreach ((uint id, LoadedLandblock? loaded, string? loadError) in finished)
        {
            if (!_window.Contains(id))
            {
                continue; // the observer moved on while it loaded
            }

            string? error = loadError;
            if (loaded is null || !ApplyLoadedTerrainLocked(id, loaded, out error))
            {
                _retryAtFrame[id] = _frame + RetryDelayFrames;
                _log($"landblock 0x{id:X8}: could not load ({error}); retrying in {RetryDelayFrames} frames.");
            }
        }

        foreach (uint id in _loaded.Where(id => !_window.Contains(id)).ToList())
        {
            UnloadLandblockLocked(id);
        }

        foreach (uint id in _retryAtFrame.Keys.Where(id => !_window.Contains(id)).ToList())
        {
            _retryAtFrame.Remove(id);
        }

        lock (_streamingLock)
        {
            if (_stopping)
            {
                return;
            }

            // Requests that left the window before the loader took them are dropped; the rest and the
            // new ones are queued nearest first.
            var queue = new List<uint>(_requests.Count + _window.Count);
            foreach (uint id in _requests)
            {
                if (_window.Contains(id))
                {
                    queue.Add(id);
                }
                else
                {
                    _pending.Remove(id);
                }
            }

            foreach (uint id in _window)
            {
                if (_loaded.Contains(id) || _pending.Contains(id)
                    || (_retryAtFrame.TryGetValue(id, out long retryAt) && _frame < retryAt))
                {
                    continue;
                }

                _retryAtFrame.Remove(id);
                _pending.Add(id);
                queue.Add(id);
            }

            _requests.Clear();
            foreach (uint id in queue.OrderBy(id => DistanceSquared(id, cx, cy)).ThenBy(id => id))
            {
                _requests.Enqueue(id);
            }

            Monitor.PulseAll(_streamingLock);
        }
    }

    /// <summary>
    /// Waits until every landblock requested so far has finished loading (or failed); the next
    /// <see cref="UpdateStreaming"/> registers them. The scene runner calls it to keep runs reproducible.
    /// </summary>
    /// <param name="timeout">How long to wait at most.</param>
    /// <returns>True when nothing is in flight any more; false on time-out.</returns>
    public bool WaitForLoads(TimeSpan timeout)
    {
        DateTime deadline = DateTime.UtcNow + timeout;
        lock (_streamingLock)
        {
            while (_completed.Count < _pending.Count)
            {
                TimeSpan left = deadline - DateTime.UtcNow;
                if (left <= TimeSpan.Zero || !Monitor.Wait(_streamingLock, left))
                {
                    return _completed.Count >= _pending.Count;
                }
            }

            return true;
        }
    }

    /// <summary>
    /// Stops the loader thread: a load in progress finishes first, queued requests are dropped.
    /// Safe to call more than once, from a <see cref="LandblockLoaded"/> or
    /// <see cref="LandblockUnloaded"/> handler or the log (they run outside the streaming lock), and
    /// from the source on the loader thread (it then does not wait for the loader to end).
    /// </summary>
    public void Dispose()
    {
        lock (_streamingLock)
        {
            _stopping = true;
            foreach (uint id in _requests)
            {
                _pending.Remove(id);
            }

            _requests.Clear();
            Monitor.PulseAll(_streamingLock);
        }

        if (Thread.CurrentThread != _loader)
        {
            _loader.Join();
        }
    }

    /// <summary>
    /// Registers a loaded landblock: builds its <see cref="TerrainSurface"/> (the game's triangles,
    /// from the landblock id), one <see cref="CellSurface"/> per cell whose environment and cell
    /// struct resolve, and one <see cref="ObjectSurface"/> per object of its <see cref="LoadedLandblock.Info"/>
    /// and of its registered cells' <see cref="EnvCell.StaticObjects"/> (<see cref="ObjectSurface.FromLandblock"/>,
    /// object by object), and calls <c>PhysicsEngine.AddLandblock</c> with them. A cell or an object
    /// that cannot be built is skipped with a warning naming it and the reason; an object standing
    /// in a skipped cell is skipped with it.
    /// </summary>
    /// <remarks>
    /// The name is the spec's (Phase B.3 hooks the engine into <c>ApplyLoadedTerrainLocked</c>). Here
    /// "locked" means "on the frame thread, which owns the engine's writes": the streaming lock is no
    /// longer held while it runs, so events and the log may call back into the window.
    /// </remarks>
    /// <returns>False, with the reason, when the landblock itself cannot be registered; the engine is then unchanged.</returns>
    internal bool ApplyLoadedTerrainLocked(uint landblockId, LoadedLandblock loaded, out string? error)
    {
        uint id = CellIds.LandblockOf(landblockId);
        error = null;
        if (loaded.LandBlock is null || CellIds.LandblockOf(loaded.LandBlock.Id) != id)
        {
            error = $"the source returned landblock 0x{loaded.LandBlock?.Id ?? 0:X8}";
            return false;
        }

        TerrainSurface terrain;
        try
        {
            terrain = new TerrainSurface(loaded.LandBlock.Height, _heightTable, id);
        }
        catch (ArgumentException e)
        {
            error = e.Message;
            return false;
        }

        var cells = new List<CellSurface>();
        var ids = new HashSet<uint>();
        foreach (EnvCell? envCell in loaded.EnvCells ?? [])
        {
            string? problem = CellProblem(id, envCell, loaded.Environments, ids, out CellSurface? cell);
            if (problem is null)
            {
                cells.Add(cell!);
                ids.Add(cell!.CellId);
            }
            else
            {
                _log($"landblock 0x{id:X8}: cell 0x{envCell?.Id ?? 0:X8} skipped: {problem}");
            }
        }

        List<ObjectSurface> objects = BuildObjects(id, loaded, ids);
        while (true)
        {
            try
            {
                Physics.AddLandblock(id, terrain, cells, objects);
                break;
            }
            catch (ObjectRefusedException e)
            {
                // The engine names the one object it refuses and why: that object is dropped, the rest kept.
                _log($"landblock 0x{id:X8}: object 0x{e.ObjectId:X8} skipped ({e.Rule}): {e.Message}");
                objects.RemoveAt(e.ObjectIndex);
            }
            catch (ArgumentException e) when (objects.Count > 0)
            {
                // Not one object's fault but their combination (more outdoor objects than the engine takes):
                // the landblock is registered without them.
                _log($"landblock 0x{id:X8}: its {objects.Count} objects skipped: {e.Message}");
                objects.Clear();
            }
            catch (ArgumentException e)
            {
                error = e.Message;
                return false;
            }
        }

        _objectCounts[id] = objects.Count;

        if (_loaded.Add(id))
        {
            LandblockLoaded?.Invoke(id);
        }

        return true;
    }

    /// <summary>The number of objects registered with each loaded landblock (<c>0xXXYYFFFF</c>), as of its last registration. Frame thread only.</summary>
    public IReadOnlyDictionary<uint, int> ObjectCounts => _objectCounts;

    /// <summary>The unload path: removes a landblock from the engine (nothing happens if it is not registered).</summary>
    internal void UnloadLandblockLocked(uint landblockId)
    {
        uint id = CellIds.LandblockOf(landblockId);
        Physics.RemoveLandblock(id);
        _objectCounts.Remove(id);
        if (_loaded.Remove(id))
        {
            LandblockUnloaded?.Invoke(id);
        }
    }

    /// <summary>
    /// The landblock's objects, built one by one (each through <see cref="ObjectSurface.FromLandblock"/>
    /// with that object alone) so a bad one is reported and skipped, as a bad cell is: the
    /// <see cref="LandBlockInfo"/>'s objects and buildings, then the static objects of each registered
    /// cell. (A building whose door cell is not registered is refused by the engine, by name, and dropped.)
    /// </summary>
    private List<ObjectSurface> BuildObjects(uint landblockId, LoadedLandblock loaded, HashSet<uint> cellIds)
    {
        var result = new List<ObjectSurface>();
        IReadOnlyDictionary<uint, GfxObj> gfxObjs = loaded.GfxObjs ?? new Dictionary<uint, GfxObj>();
        IReadOnlyDictionary<uint, Setup> setups = loaded.Setups ?? new Dictionary<uint, Setup>();
        void Build(string what, LandBlockInfo? info, EnvCell? cell)
        {
            try
            {
                result.AddRange(ObjectSurface.FromLandblock(landblockId, info, cell is null ? [] : [cell], gfxObjs, setups));
            }
            catch (ArgumentException e)
            {
                _log($"landblock 0x{landblockId:X8}: {what} skipped: {e.Message}");
            }
        }

        if (loaded.Info is LandBlockInfo info)
        {
            if (info.Id != 0 && CellIds.LandblockOf(info.Id) != landblockId)
            {
                _log($"landblock 0x{landblockId:X8}: its object list 0x{info.Id:X8} skipped: it belongs to another landblock");
            }
            else
            {
                for (int i = 0; i < (info.Objects?.Count ?? 0); i++)
                {
                    Stab stab = info.Objects![i];
                    Build($"object {i} (0x{stab?.Id ?? 0:X8})", new LandBlockInfo { Id = info.Id, Objects = [stab!] }, null);
                }

                for (int i = 0; i < (info.Buildings?.Count ?? 0); i++)
                {
                    BuildingInfo building = info.Buildings![i];
                    string what = $"building {i} (0x{building?.ModelId ?? 0:X8})";
                    Build(what, new LandBlockInfo { Id = info.Id, Buildings = [building!] }, null);
                }
            }
        }

        foreach (EnvCell? envCell in loaded.EnvCells ?? [])
        {
            if (envCell?.StaticObjects is not { Count: > 0 } statics)
            {
                continue;
            }

            if (!cellIds.Contains(envCell.Id))
            {
                _log($"landblock 0x{landblockId:X8}: the {statics.Count} object(s) of cell 0x{envCell.Id:X8} skipped with their cell");
                continue;
            }

            for (int i = 0; i < statics.Count; i++)
            {
                Build($"object {i} (0x{statics[i]?.Id ?? 0:X8}) of cell 0x{envCell.Id:X8}", null, new EnvCell { Id = envCell.Id, StaticObjects = [statics[i]] });
            }
        }

        return result;
    }

    private static string? CellProblem(uint landblockId, EnvCell? envCell, IReadOnlyDictionary<uint, Environment>? environments, HashSet<uint> ids, out CellSurface? cell)
    {
        cell = null;
        if (envCell is null)
        {
            return "the cell is null";
        }

        if (CellIds.LandblockOf(envCell.Id) != CellIds.LandblockOf(landblockId))
        {
            return "the cell belongs to another landblock";
        }

        if (ids.Contains(envCell.Id))
        {
            return "the cell is listed twice";
        }

        uint environmentId = 0x0D000000u | envCell.EnvironmentId;
        if (environments is null || !environments.TryGetValue(environmentId, out Environment? environment) || environment is null)
        {
            return $"environment 0x{environmentId:X8} is missing";
        }

        if (environment.Cells is null || !environment.Cells.TryGetValue(envCell.CellStructure, out CellStruct? cellStruct) || cellStruct is null)
        {
            return $"cell struct {envCell.CellStructure} is missing from environment 0x{environmentId:X8}";
        }

        try
        {
            cell = new CellSurface(envCell.Id, envCell, cellStruct);
            return null;
        }
        catch (ArgumentException e)
        {
            return e.Message;
        }
    }

    private static int DistanceSquared(uint id, int cx, int cy)
    {
        int dx = CellIds.LandblockX(id) - cx, dy = CellIds.LandblockY(id) - cy;
        return (dx * dx) + (dy * dy);
    }

    private void LoaderLoop()
    {
        while (true)
        {
            uint id;
            lock (_streamingLock)
            {
                while (_requests.Count == 0 && !_stopping)
                {
                    Monitor.Wait(_streamingLock);
                }

                if (_stopping)
                {
                    return;
                }

                id = _requests.Dequeue();
            }

            LoadedLandblock? loaded = null;
            string? error = null;
            try
            {
                loaded = _source.Load(id) ?? throw new InvalidDataException("the source returned nothing");
            }
#pragma warning disable CA1031 // any failure of the source is a failed load, reported and retried by the frame loop
            catch (Exception e)
#pragma warning restore CA1031
            {
                error = e.Message;
            }

            lock (_streamingLock)
            {
                _completed.Enqueue((id, loaded, error));
                Monitor.PulseAll(_streamingLock);
            }
        }
    }
}

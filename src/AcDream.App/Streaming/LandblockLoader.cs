namespace AcDream.App.Streaming;

/// <summary>
/// The loader thread: reads the requested landblocks from an <see cref="ILandblockSource"/> in the
/// background, one at a time in queue order, and keeps each result (the landblock, or why it could
/// not be read) until the frame thread takes it with <see cref="TakeFinished"/>.
/// </summary>
/// <remarks>
/// The loader thread only reads from the source. It and the frame thread share only the request
/// queue, the result queue and the set of landblocks in flight, under a lock inside which no
/// callback of the window runs (the two delegates of <see cref="Request"/> only read the frame
/// thread's state).
/// </remarks>
internal sealed class LandblockLoader : IDisposable
{
    private readonly ILandblockSource _source;

    // Guarded by _lock: the loader's inbox and outbox, and what is in flight.
    private readonly object _lock = new();
    private readonly Queue<uint> _requests = new();
    private readonly Queue<(uint Id, LoadedLandblock? Loaded, string? Error)> _completed = new();
    private readonly HashSet<uint> _pending = [];
    private readonly Thread _thread;
    private bool _stopping;

    /// <summary>Starts the loader thread; it waits for the first <see cref="Request"/>.</summary>
    /// <param name="source">Where landblocks come from; called on the loader thread.</param>
    public LandblockLoader(ILandblockSource source)
    {
        _source = source;
        _thread = new Thread(Run) { IsBackground = true, Name = "landblock loader" };
        _thread.Start();
    }

    /// <summary>
    /// The loads that finished (or failed) since the last call, in the order they finished: each
    /// landblock (<c>0xXXYYFFFF</c>) with what the source returned, or the reason it failed. They are
    /// no longer in flight.
    /// </summary>
    public List<(uint Id, LoadedLandblock? Loaded, string? Error)> TakeFinished()
    {
        lock (_lock)
        {
            List<(uint Id, LoadedLandblock? Loaded, string? Error)> finished = [.. _completed];
            _completed.Clear();
            foreach ((uint id, _, _) in finished)
            {
                _pending.Remove(id);
            }

            return finished;
        }
    }

    /// <summary>
    /// Replaces the queue: queued requests outside <paramref name="window"/> are dropped, the rest are
    /// kept, and each landblock of the window that is not in flight and that <paramref name="wanted"/>
    /// accepts is added; the loader takes the queue in order of <paramref name="distance"/>, then of id.
    /// After <see cref="Dispose"/> nothing is queued.
    /// </summary>
    /// <param name="window">The landblocks (<c>0xXXYYFFFF</c>) wanted now.</param>
    /// <param name="wanted">Whether a landblock of the window not in flight is to be loaded; called under the lock.</param>
    /// <param name="distance">A landblock's place in the queue, smallest first; called under the lock.</param>
    /// <returns>The landblocks added to the queue by this call.</returns>
    public List<uint> Request(IReadOnlySet<uint> window, Func<uint, bool> wanted, Func<uint, int> distance)
    {
        var added = new List<uint>();
        lock (_lock)
        {
            if (_stopping)
            {
                return added;
            }

            // Requests that left the window before the loader took them are dropped; the rest and the
            // new ones are queued nearest first.
            var queue = new List<uint>(_requests.Count + window.Count);
            foreach (uint id in _requests)
            {
                if (window.Contains(id))
                {
                    queue.Add(id);
                }
                else
                {
                    _pending.Remove(id);
                }
            }

            foreach (uint id in window)
            {
                if (_pending.Contains(id) || !wanted(id))
                {
                    continue;
                }

                added.Add(id);
                _pending.Add(id);
                queue.Add(id);
            }

            _requests.Clear();
            foreach (uint id in queue.OrderBy(distance).ThenBy(id => id))
            {
                _requests.Enqueue(id);
            }

            Monitor.PulseAll(_lock);
        }

        return added;
    }

    /// <summary>Waits until every landblock requested so far has finished loading (or failed).</summary>
    /// <param name="timeout">How long to wait at most.</param>
    /// <returns>True when nothing is in flight any more; false on time-out.</returns>
    public bool WaitForLoads(TimeSpan timeout)
    {
        DateTime deadline = DateTime.UtcNow + timeout;
        lock (_lock)
        {
            while (_completed.Count < _pending.Count)
            {
                TimeSpan left = deadline - DateTime.UtcNow;
                if (left <= TimeSpan.Zero || !Monitor.Wait(_lock, left))
                {
                    return _completed.Count >= _pending.Count;
                }
            }

            return true;
        }
    }

    /// <summary>
    /// Stops the loader thread: a load in progress finishes first, queued requests are dropped.
    /// Safe to call more than once, and from the source on the loader thread (it then does not wait
    /// for the loader to end).
    /// </summary>
    public void Dispose()
    {
        lock (_lock)
        {
            _stopping = true;
            foreach (uint id in _requests)
            {
                _pending.Remove(id);
            }

            _requests.Clear();
            Monitor.PulseAll(_lock);
        }

        if (Thread.CurrentThread != _thread)
        {
            _thread.Join();
        }
    }

    private void Run()
    {
        while (true)
        {
            uint id;
            lock (_lock)
            {
                while (_requests.Count == 0 && !_stopping)
                {
                    Monitor.Wait(_lock);
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

            lock (_lock)
            {
                _completed.Enqueue((id, loaded, error));
                Monitor.PulseAll(_lock);
            }
        }
    }
}
